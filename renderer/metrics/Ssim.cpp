#include "renderer/metrics/Ssim.h"

#include <algorithm>
#include <cmath>

#include "renderer/Error.h"
#include "renderer/metrics/DifferenceStatistics.h"

namespace dw {

const char* ssimEncodingName(SsimEncoding e) {
    switch (e) {
        case SsimEncoding::AsStored: return "as-stored";
        case SsimEncoding::Reinhard: return "reinhard";
    }
    return "?";
}

namespace {

// scipy.ndimage's "reflect" boundary: the image mirrored about its edge,
// repeating with period 2n (so any offset maps inside).
int reflectIndex(int i, int n) {
    const int period = 2 * n;
    int m = i % period;
    if (m < 0) m += period;
    return m < n ? m : period - 1 - m;
}

// A plane of doubles, width x height.
struct Plane {
    int width = 0, height = 0;
    std::vector<double> v;
};

// The separable Gaussian filter: along x, then along y (rows padded once by
// reflection; columns summed a whole row at a time).
Plane gaussianFilter(const Plane& in, const std::vector<double>& kernel) {
    const int w = in.width, h = in.height;
    const int r = static_cast<int>(kernel.size() / 2);
    Plane tmp{w, h, std::vector<double>(in.v.size())};
    std::vector<double> padded(static_cast<size_t>(w + 2 * r));
    for (int y = 0; y < h; ++y) {
        const double* row = &in.v[static_cast<size_t>(y) * w];
        for (int x = -r; x < w + r; ++x) padded[static_cast<size_t>(x + r)] = row[reflectIndex(x, w)];
        double* out = &tmp.v[static_cast<size_t>(y) * w];
        for (int x = 0; x < w; ++x) {
            const double* p = &padded[static_cast<size_t>(x)];
            double s = 0;
            for (size_t k = 0; k < kernel.size(); ++k) s += kernel[k] * p[k];
            out[x] = s;
        }
    }
    Plane out{w, h, std::vector<double>(in.v.size(), 0.0)};
    for (int y = 0; y < h; ++y) {
        double* o = &out.v[static_cast<size_t>(y) * w];
        for (int k = -r; k <= r; ++k) {
            const double weight = kernel[static_cast<size_t>(k + r)];
            const double* src = &tmp.v[static_cast<size_t>(reflectIndex(y + k, h)) * w];
            for (int x = 0; x < w; ++x) o[x] += weight * src[x];
        }
    }
    return out;
}

}  // namespace

int Ssim::windowRadius(const SsimParameters& p) { return static_cast<int>(p.truncate * p.sigma + 0.5); }

FloatImage Ssim::encode(const FloatImage& image, SsimEncoding encoding) {
    FloatImage out = image;
    if (encoding == SsimEncoding::Reinhard)
        for (float& v : out.pixels) {
            const double x = std::max(0.0, static_cast<double>(v));
            v = static_cast<float>(x / (1.0 + x));
        }
    return out;
}

SsimResult Ssim::compute(const FloatImage& a, const FloatImage& b, const SsimParameters& p) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        throw Error("SSIM: the images differ in shape (" + DifferenceStatistics::shape(a) + " vs " +
                    DifferenceStatistics::shape(b) + ")");
    const int r = windowRadius(p);
    const int window = 2 * r + 1;
    if (a.width < window || a.height < window)
        throw Error("SSIM needs an image of at least " + std::to_string(window) + "x" + std::to_string(window) +
                    " pixels (its Gaussian window), got " + std::to_string(a.width) + "x" + std::to_string(a.height));
    // The 1-D window: exp(-k^2 / (2 sigma^2)) for k in [-r, r], normalised.
    std::vector<double> kernel(static_cast<size_t>(window));
    double sum = 0;
    for (int k = -r; k <= r; ++k) sum += kernel[static_cast<size_t>(k + r)] = std::exp(-0.5 * k * k / (p.sigma * p.sigma));
    for (double& w : kernel) w /= sum;

    const double c1 = (p.k1 * p.dataRange) * (p.k1 * p.dataRange);
    const double c2 = (p.k2 * p.dataRange) * (p.k2 * p.dataRange);
    const size_t n = static_cast<size_t>(a.width) * a.height;
    SsimResult result;
    result.map.width = a.width;
    result.map.height = a.height;
    result.map.channels = a.channels;
    result.map.pixels.assign(n * a.channels, 0.0f);
    for (int c = 0; c < a.channels; ++c) {
        Plane x{a.width, a.height, std::vector<double>(n)}, y = x, xx = x, yy = x, xy = x;
        for (size_t i = 0; i < n; ++i) {
            const double va = a.pixels[i * a.channels + c], vb = b.pixels[i * a.channels + c];
            x.v[i] = va;
            y.v[i] = vb;
            xx.v[i] = va * va;
            yy.v[i] = vb * vb;
            xy.v[i] = va * vb;
        }
        const Plane ux = gaussianFilter(x, kernel), uy = gaussianFilter(y, kernel);
        const Plane uxx = gaussianFilter(xx, kernel), uyy = gaussianFilter(yy, kernel), uxy = gaussianFilter(xy, kernel);
        double interior = 0;
        long long count = 0;
        for (int py = 0; py < a.height; ++py)
            for (int px = 0; px < a.width; ++px) {
                const size_t i = static_cast<size_t>(py) * a.width + px;
                const double mx = ux.v[i], my = uy.v[i];
                const double vx = uxx.v[i] - mx * mx, vy = uyy.v[i] - my * my, vxy = uxy.v[i] - mx * my;
                const double s = ((2 * mx * my + c1) * (2 * vxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
                result.map.pixels[i * a.channels + c] = static_cast<float>(s);
                if (px >= r && px < a.width - r && py >= r && py < a.height - r) {
                    interior += s;
                    ++count;
                }
            }
        result.perChannel.push_back(interior / static_cast<double>(count));
    }
    double total = 0;
    for (double v : result.perChannel) total += v;
    result.mean = total / static_cast<double>(result.perChannel.size());
    return result;
}

}  // namespace dw
