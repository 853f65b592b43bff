#include "renderer/bench/ImageError.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/Error.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/metrics/ImageComparison.h"
#include "renderer/metrics/MaskedMetrics.h"
#include "renderer/metrics/ShadowEdgeMask.h"

namespace dw {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Per-tile sums of a per-pixel quantity (`perPixel(x, y)`), and pixel counts.
// Only the pixels of `mask` (> 0.5) when there is one.
template <class F>
void tileSums(int width, int height, F perPixel, std::vector<double>& sums, std::vector<double>& counts,
              const FloatImage* mask) {
    const int tx = (width + ImageError::kTile - 1) / ImageError::kTile, ty = (height + ImageError::kTile - 1) / ImageError::kTile;
    sums.assign(static_cast<size_t>(tx) * ty, 0.0);
    counts.assign(sums.size(), 0.0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (mask && !(mask->at(x, y, 0) > 0.5f)) continue;
            const size_t t = static_cast<size_t>(y / ImageError::kTile) * tx + static_cast<size_t>(x / ImageError::kTile);
            sums[t] += perPixel(x, y);
            counts[t] += 1.0;
        }
}

}  // namespace

double ErrorTiles::valueOf(double sum, double count) const {
    if (!(count > 0.0)) return kNaN;
    const double mean = sum / count;
    if (metric == "rms") return std::sqrt(mean);
    if (metric == "psnr") return mean > 0.0 ? 10.0 * std::log10(peak2 / mean) : std::numeric_limits<double>::infinity();
    if (metric == "ssim") return mean + shift;
    return mean;
}

const std::vector<std::string>& ImageError::metrics() {
    static const std::vector<std::string> names = {"flip", "rms", "psnr", "ssim"};
    return names;
}

ErrorEstimate ImageError::measure(const FloatImage& reference, const FloatImage& test, const std::string& metric, bool hdr,
                                  int resamples, std::uint64_t seed, const FloatImage* mask) {
    const auto& known = metrics();
    if (std::find(known.begin(), known.end(), metric) == known.end())
        throw Error("--metric: expected flip, rms, psnr or ssim, got '" + metric + "'");
    ComparisonSettings settings;
    settings.hdr = hdr;
    settings.ssim = metric == "ssim";
    settings.flipMetric = metric == "flip";
    const ImageComparison c = ImageComparison::measure(reference, test, settings);
    if (mask) {
        if (mask->width != reference.width || mask->height != reference.height || mask->channels != 1)
            throw Error("the error mask is " + std::to_string(mask->width) + "x" + std::to_string(mask->height) + "x" +
                        std::to_string(mask->channels) + ", the images " + std::to_string(reference.width) + "x" +
                        std::to_string(reference.height) + " (expected the images' size, 1 channel)");
        if (ShadowEdgeMask::count(*mask) == 0) throw Error("the mask selects no pixel");
    }
    ErrorEstimate e;
    std::vector<double> sums, counts;
    const int w = reference.width, h = reference.height, ch = reference.channels;
    if (metric == "rms" || metric == "psnr") {
        const FloatImage& d = c.absoluteDifference;
        tileSums(w, h, [&](int x, int y) {
            double s = 0.0;
            for (int k = 0; k < ch; ++k) s += double(d.at(x, y, k)) * d.at(x, y, k);
            return s / ch;
        }, sums, counts, mask);
        const Interval mse = bootstrapGroupMean(sums, counts, resamples, seed);
        const double rms = mask ? MaskedMetrics::rms(reference, test, *mask) : c.difference.overall.rms;
        if (metric == "rms") {
            e.value = rms;
            e.low = mse.valid() ? std::sqrt(mse.low) : kNaN;
            e.high = mse.valid() ? std::sqrt(mse.high) : kNaN;
        } else {
            // PSNR = 10 log10(peak^2 / MSE) with OIIO's peak, recovered from its own PSNR.
            e.value = mask ? MaskedMetrics::psnr(reference, test, *mask) : c.difference.overall.psnr;
            const double peak2 = mask ? 1.0 : rms > 0.0 ? rms * rms * std::pow(10.0, e.value / 10.0) : kNaN;
            auto psnr = [&](double m) { return m > 0.0 ? 10.0 * std::log10(peak2 / m) : std::numeric_limits<double>::infinity(); };
            e.low = mse.valid() && rms > 0.0 ? psnr(mse.high) : e.value;  // the larger MSE, the lower PSNR
            e.high = mse.valid() && rms > 0.0 ? psnr(mse.low) : e.value;
            e.tiles.peak2 = peak2;
        }
        e.tiles = {metric, std::move(sums), std::move(counts), e.tiles.peak2, 0.0};
        return e;
    }
    if (metric == "flip") {
        if (!c.flip) throw Error("FLIP cannot be measured here: " + (c.notes.empty() ? std::string("no reason given") : c.notes.front()));
        e.value = mask ? MaskedMetrics::mapMean(c.flip->map, *mask) : c.flip->mean;
        tileSums(w, h, [&](int x, int y) { return double(c.flip->map.at(x, y, 0)); }, sums, counts, mask);
        const Interval i = bootstrapGroupMean(sums, counts, resamples, seed);
        e.low = i.valid() ? i.low : kNaN;
        e.high = i.valid() ? i.high : kNaN;
        e.tiles = {metric, std::move(sums), std::move(counts), 1.0, 0.0};
        return e;
    }
    // ssim
    if (!c.ssim) throw Error("SSIM cannot be measured here: " + (c.notes.empty() ? std::string("no reason given") : c.notes.front()));
    const FloatImage& m = c.ssim->map;
    e.value = mask ? MaskedMetrics::mapMean(m, *mask) : c.ssim->mean;
    const int channels = static_cast<int>(std::max<size_t>(1, c.ssim->perChannel.size()));
    tileSums(w, h, [&](int x, int y) {
        double s = 0.0;
        for (int k = 0; k < channels && k < m.channels; ++k) s += m.at(x, y, k);
        return s / std::min(channels, m.channels);
    }, sums, counts, mask);
    double all = 0.0, n = 0.0;
    for (size_t t = 0; t < sums.size(); ++t) {
        all += sums[t];
        n += counts[t];
    }
    const Interval i = bootstrapGroupMean(sums, counts, resamples, seed);
    const double shift = n > 0.0 ? e.value - all / n : 0.0;
    e.low = i.valid() ? i.low + shift : kNaN;
    e.high = i.valid() ? i.high + shift : kNaN;
    e.tiles = {metric, std::move(sums), std::move(counts), 1.0, shift};
    return e;
}

ErrorEstimate ImageError::meanOver(const std::vector<double>& values, int resamples, std::uint64_t seed) {
    ErrorEstimate e;
    // The cameras with an error (NaN: that camera has none, e.g. no masked pixel).
    std::vector<double> finite;
    for (double v : values)
        if (!std::isnan(v)) finite.push_back(v);
    if (finite.empty()) {
        e.value = e.low = e.high = kNaN;
        return e;
    }
    double sum = 0.0;
    for (double v : finite) sum += v;
    e.value = sum / static_cast<double>(finite.size());
    if (!std::isfinite(e.value)) {  // a PSNR of inf on a camera: the mean is inf, with no interval
        e.low = e.high = kNaN;
        return e;
    }
    const Interval i = bootstrapGroupMean(finite, std::vector<double>(finite.size(), 1.0), resamples, seed);
    e.low = i.low;
    e.high = i.high;
    return e;
}

}  // namespace dw
