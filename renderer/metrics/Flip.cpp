#include "renderer/metrics/Flip.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <thread>
#include <vector>

#include "renderer/Error.h"
#include "renderer/OptionLimits.h"
#include "renderer/metrics/DifferenceStatistics.h"

namespace dw {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The paper's constants (HPG 2020, section 4 and table 1).
constexpr double kQc = 0.7;    // colour difference exponent
constexpr double kPc = 0.4;    // colour difference: fraction of cmax where the compression starts
constexpr double kPt = 0.95;   // ... and the FLIP value it maps to
constexpr double kW = 0.082;   // feature filter: width in degrees (sigma = w / 2)
constexpr double kQf = 0.5;    // feature difference exponent
// Contrast sensitivity functions as spatial kernels a sqrt(pi / b) exp(-pi^2 r^2 / b).
constexpr double kAchromaticA = 1.0, kAchromaticB = 0.0047;
constexpr double kRedGreenA = 1.0, kRedGreenB = 0.0053;
constexpr double kBlueYellowA1 = 34.1, kBlueYellowB1 = 0.04;
constexpr double kBlueYellowA2 = 13.5, kBlueYellowB2 = 0.025;

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

// Linear sRGB (Rec. 709 primaries, D65) to CIE XYZ, and its inverse.
constexpr double kRgbToXyz[3][3] = {{0.4123865632529917, 0.357584339383878, 0.1804807884018343},
                                    {0.21263900587151036, 0.715168678767756, 0.07219231536073371},
                                    {0.01933081871559185, 0.11919477979462598, 0.9505321522496606}};

Vec3 mul(const double m[3][3], Vec3 v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

struct Inverse3 {
    double m[3][3];
    Inverse3() {
        const auto& a = kRgbToXyz;
        const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        m[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
        m[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
        m[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
        m[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
        m[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
        m[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
        m[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
        m[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
        m[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
    }
};
const Inverse3 kXyzToRgb;

// The reference white: XYZ of linear RGB (1, 1, 1), so grey has a = b = 0.
const Vec3 kWhite = mul(kRgbToXyz, {1, 1, 1});

double srgbToLinear(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

Vec3 linearToYCxCz(Vec3 rgb) {
    const Vec3 xyz = mul(kRgbToXyz, rgb);
    const double x = xyz.x / kWhite.x, y = xyz.y / kWhite.y, z = xyz.z / kWhite.z;
    return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Vec3 yCxCzToLinear(Vec3 c) {
    const double y = (c.x + 16.0) / 116.0;
    const Vec3 xyz{(y + c.y / 500.0) * kWhite.x, y * kWhite.y, (y - c.z / 200.0) * kWhite.z};
    return mul(kXyzToRgb.m, xyz);
}

double labF(double t) {
    constexpr double d = 6.0 / 29.0;
    return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

// CIELAB with the Hunt adjustment: a and b scaled by 0.01 L.
Vec3 linearToHuntLab(Vec3 rgb) {
    const Vec3 xyz = mul(kRgbToXyz, rgb);
    const double fx = labF(xyz.x / kWhite.x), fy = labF(xyz.y / kWhite.y), fz = labF(xyz.z / kWhite.z);
    const double L = 116.0 * fy - 16.0;
    return {L, 0.01 * L * 500.0 * (fx - fy), 0.01 * L * 200.0 * (fy - fz)};
}

double hyab(Vec3 p, Vec3 q) { return std::fabs(p.x - q.x) + std::hypot(p.y - q.y, p.z - q.z); }

// cmax: the HyAB distance of green and blue (Hunt-adjusted), to the power qc.
double maxColourDifference() {
    return std::pow(hyab(linearToHuntLab({0, 1, 0}), linearToHuntLab({0, 0, 1})), kQc);
}

struct Plane {
    int width = 0, height = 0;
    std::vector<double> v;
    double at(int x, int y) const { return v[static_cast<size_t>(y) * width + x]; }
};

// Separable convolution, kx along rows then ky along columns; outside the
// image the edge pixel repeats. Rows are padded once and columns are summed a
// whole row at a time, so the inner loops run over contiguous memory.
Plane convolve(const Plane& in, const std::vector<double>& kx, const std::vector<double>& ky) {
    const int w = in.width, h = in.height;
    const int rx = static_cast<int>(kx.size() / 2), ry = static_cast<int>(ky.size() / 2);
    Plane tmp{w, h, std::vector<double>(in.v.size())};
    std::vector<double> padded(static_cast<size_t>(w + 2 * rx));
    for (int y = 0; y < h; ++y) {
        const double* row = &in.v[static_cast<size_t>(y) * w];
        for (int x = -rx; x < w + rx; ++x) padded[static_cast<size_t>(x + rx)] = row[std::clamp(x, 0, w - 1)];
        double* out = &tmp.v[static_cast<size_t>(y) * w];
        for (int x = 0; x < w; ++x) {
            const double* p = &padded[static_cast<size_t>(x)];
            double s = 0;
            for (size_t k = 0; k < kx.size(); ++k) s += kx[k] * p[k];
            out[x] = s;
        }
    }
    Plane out{w, h, std::vector<double>(in.v.size(), 0.0)};
    for (int y = 0; y < h; ++y) {
        double* o = &out.v[static_cast<size_t>(y) * w];
        for (int k = -ry; k <= ry; ++k) {
            const double weight = ky[static_cast<size_t>(k + ry)];
            const double* src = &tmp.v[static_cast<size_t>(std::clamp(y + k, 0, h - 1)) * w];
            for (int x = 0; x < w; ++x) o[x] += weight * src[x];
        }
    }
    return out;
}

// The colour filters. A 2-D kernel a sqrt(pi/b) exp(-pi^2 (x^2 + y^2) / b) is
// the outer product of two 1-D kernels sqrt(a sqrt(pi/b)) exp(-pi^2 x^2 / b).
struct ColourFilters {
    std::vector<double> achromatic, redGreen, blueYellow1, blueYellow2;
};

ColourFilters colourFilters(double ppd) {
    const double bMax = std::max({kAchromaticB, kRedGreenB, kBlueYellowB1, kBlueYellowB2});
    const int radius = static_cast<int>(std::ceil(3.0 * std::sqrt(bMax / (2.0 * kPi * kPi)) * ppd));
    auto oneD = [&](double a, double b) {
        std::vector<double> k(static_cast<size_t>(2 * radius + 1));
        for (int i = -radius; i <= radius; ++i) {
            const double x = i / ppd;  // degrees
            k[static_cast<size_t>(i + radius)] = std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x * x / b);
        }
        return k;
    };
    auto sum = [](const std::vector<double>& k) {
        double s = 0;
        for (double v : k) s += v;
        return s;
    };
    ColourFilters f{oneD(kAchromaticA, kAchromaticB), oneD(kRedGreenA, kRedGreenB), oneD(kBlueYellowA1, kBlueYellowB1),
                    oneD(kBlueYellowA2, kBlueYellowB2)};
    // Each 2-D kernel sums to 1: a single Gaussian's 1-D factor sums to 1; the
    // blue-yellow pair's 2-D sums S1^2 + S2^2 share one factor.
    for (auto* k : {&f.achromatic, &f.redGreen}) {
        const double s = sum(*k);
        for (double& v : *k) v /= s;
    }
    const double s1 = sum(f.blueYellow1), s2 = sum(f.blueYellow2);
    const double norm = std::sqrt(s1 * s1 + s2 * s2);
    for (auto* k : {&f.blueYellow1, &f.blueYellow2})
        for (double& v : *k) v /= norm;
    return f;
}

// The feature filters: a Gaussian (sum 1), its first and second derivatives
// (positive weights sum to 1, negative to -1).
struct FeatureFilters {
    std::vector<double> gauss, first, second;
};

FeatureFilters featureFilters(double ppd) {
    const double sigma = 0.5 * kW * ppd;
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    FeatureFilters f;
    double gSum = 0, d1Pos = 0, d1Neg = 0, d2Pos = 0, d2Neg = 0;
    for (int i = -radius; i <= radius; ++i) {
        const double g = std::exp(-(i * i) / (2.0 * sigma * sigma));
        const double d1 = -i * g;
        const double d2 = (i * i / (sigma * sigma) - 1.0) * g;
        f.gauss.push_back(g);
        f.first.push_back(d1);
        f.second.push_back(d2);
        gSum += g;
        (d1 > 0 ? d1Pos : d1Neg) += std::fabs(d1);
        (d2 > 0 ? d2Pos : d2Neg) += std::fabs(d2);
    }
    for (double& v : f.gauss) v /= gSum;
    for (double& v : f.first) v /= v > 0 ? d1Pos : d1Neg;
    for (double& v : f.second) v /= v > 0 ? d2Pos : d2Neg;
    return f;
}

// RGB of pixel i (1 channel: grey).
Vec3 rgbAt(const FloatImage& img, size_t i) {
    const float* p = &img.pixels[i * static_cast<size_t>(img.channels)];
    if (img.channels < 3) return {p[0], p[0], p[0]};
    return {p[0], p[1], p[2]};
}

void checkInputs(const FloatImage& reference, const FloatImage& test) {
    if (reference.width != test.width || reference.height != test.height || reference.channels != test.channels)
        throw Error("FLIP: the images differ in shape (" + DifferenceStatistics::shape(reference) + " vs " +
                    DifferenceStatistics::shape(test) + ")");
    if (reference.channels == 2 || reference.channels < 1)
        throw Error("FLIP needs 1 (grey), 3 or 4 (RGB, alpha ignored) channels, got " + std::to_string(reference.channels));
    if (reference.width < 1 || reference.height < 1) throw Error("FLIP: the images have no pixels");
}

// LDR-FLIP of two linear RGB images in [0, 1] (width x height, RGB triples).
std::vector<double> ldrFlipLinear(const std::vector<Vec3>& ref, const std::vector<Vec3>& test, int w, int h,
                                  double ppd) {
    const size_t n = static_cast<size_t>(w) * h;
    const ColourFilters cf = colourFilters(ppd);
    const FeatureFilters ff = featureFilters(ppd);
    const double cmax = maxColourDifference();
    const double pccmax = kPc * cmax;

    struct Filtered {
        std::vector<Vec3> huntLab;  // after the CSF, clamped, Hunt-adjusted CIELAB
        Plane edgeX, edgeY, pointX, pointY;
    };
    auto process = [&](const std::vector<Vec3>& img) {
        Plane Y{w, h, std::vector<double>(n)}, Cx = Y, Cz = Y, grey = Y;
        for (size_t i = 0; i < n; ++i) {
            const Vec3 c = linearToYCxCz(img[i]);
            Y.v[i] = c.x;
            Cx.v[i] = c.y;
            Cz.v[i] = c.z;
            grey.v[i] = (c.x + 16.0) / 116.0;
        }
        const Plane fy = convolve(Y, cf.achromatic, cf.achromatic);
        const Plane fcx = convolve(Cx, cf.redGreen, cf.redGreen);
        const Plane fcz1 = convolve(Cz, cf.blueYellow1, cf.blueYellow1);
        const Plane fcz2 = convolve(Cz, cf.blueYellow2, cf.blueYellow2);
        Filtered f;
        f.huntLab.resize(n);
        for (size_t i = 0; i < n; ++i) {
            Vec3 rgb = yCxCzToLinear({fy.v[i], fcx.v[i], fcz1.v[i] + fcz2.v[i]});
            rgb = {std::clamp(rgb.x, 0.0, 1.0), std::clamp(rgb.y, 0.0, 1.0), std::clamp(rgb.z, 0.0, 1.0)};
            f.huntLab[i] = linearToHuntLab(rgb);
        }
        f.edgeX = convolve(grey, ff.first, ff.gauss);
        f.edgeY = convolve(grey, ff.gauss, ff.first);
        f.pointX = convolve(grey, ff.second, ff.gauss);
        f.pointY = convolve(grey, ff.gauss, ff.second);
        return f;
    };
    const Filtered r = process(ref), t = process(test);
    std::vector<double> out(n);
    for (size_t i = 0; i < n; ++i) {
        double colour = std::pow(hyab(r.huntLab[i], t.huntLab[i]), kQc);
        colour = colour < pccmax ? colour * (kPt / pccmax) : kPt + (colour - pccmax) / (cmax - pccmax) * (1.0 - kPt);
        const double edge = std::fabs(std::hypot(r.edgeX.v[i], r.edgeY.v[i]) - std::hypot(t.edgeX.v[i], t.edgeY.v[i]));
        const double point =
            std::fabs(std::hypot(r.pointX.v[i], r.pointY.v[i]) - std::hypot(t.pointX.v[i], t.pointY.v[i]));
        const double feature = std::pow(std::max(edge, point) / std::sqrt(2.0), kQf);
        out[i] = std::pow(colour, 1.0 - feature);
    }
    return out;
}

FlipResult toResult(const std::vector<double>& values, int w, int h) {
    FlipResult r;
    r.map.width = w;
    r.map.height = h;
    r.map.channels = 1;
    r.map.pixels.resize(values.size());
    double sum = 0;
    for (size_t i = 0; i < values.size(); ++i) {
        r.map.pixels[i] = static_cast<float>(values[i]);
        sum += values[i];
    }
    r.mean = sum / static_cast<double>(values.size());
    return r;
}

// Held to limits::kPixelsPerDegree (compare --ppd's range) for every caller:
// the filters' radius grows with it and overflows an int past about 1e9.
double resolvePpd(const FlipParameters& p) {
    if (p.pixelsPerDegree == 0) return Flip::defaultPixelsPerDegree();
    if (!limits::kPixelsPerDegree.holds(p.pixelsPerDegree)) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "FLIP: pixels per degree must be from %g to %g (0: the default), got %g",
                      limits::kPixelsPerDegree.min, limits::kPixelsPerDegree.max, p.pixelsPerDegree);
        throw Error(buf);
    }
    return p.pixelsPerDegree;
}

// The ACES fit's coefficients: (A x^2 + B x + C) / (D x^2 + E x + F), with
// Narkowicz's 0.6 pre-exposure multiplied in.
constexpr double kAcesA = 0.6 * 0.6 * 2.51, kAcesB = 0.6 * 0.03, kAcesC = 0.0;
constexpr double kAcesD = 0.6 * 0.6 * 2.43, kAcesE = 0.6 * 0.59, kAcesF = 0.14;

}  // namespace

double Flip::pixelsPerDegree(double distance, double resolutionX, double monitorWidth) {
    return distance * (resolutionX / monitorWidth) * (kPi / 180.0);
}

double Flip::acesToneMap(double x) {
    return (kAcesA * x * x + kAcesB * x + kAcesC) / (kAcesD * x * x + kAcesE * x + kAcesF);
}

FlipResult Flip::ldr(const FloatImage& reference, const FloatImage& test, const FlipParameters& parameters) {
    checkInputs(reference, test);
    const double ppd = resolvePpd(parameters);
    const size_t n = static_cast<size_t>(reference.width) * reference.height;
    std::vector<Vec3> r(n), t(n);
    for (size_t i = 0; i < n; ++i) {
        const Vec3 a = rgbAt(reference, i), b = rgbAt(test, i);
        r[i] = {srgbToLinear(a.x), srgbToLinear(a.y), srgbToLinear(a.z)};
        t[i] = {srgbToLinear(b.x), srgbToLinear(b.y), srgbToLinear(b.z)};
    }
    FlipResult result = toResult(ldrFlipLinear(r, t, reference.width, reference.height, ppd), reference.width,
                                 reference.height);
    result.pixelsPerDegree = ppd;
    return result;
}

FlipResult Flip::hdr(const FloatImage& reference, const FloatImage& test, const FlipParameters& parameters) {
    checkInputs(reference, test);
    const double ppd = resolvePpd(parameters);
    const int w = reference.width, h = reference.height;
    const size_t n = static_cast<size_t>(w) * h;
    std::vector<Vec3> referenceRgb(n), testRgb(n);
    for (size_t i = 0; i < n; ++i) {
        referenceRgb[i] = rgbAt(reference, i);
        testRgb[i] = rgbAt(test, i);
    }
    // The exposure range from the reference's luminance (HDR-FLIP, section 3):
    // the start makes its brightest pixel reach 0.85 after tone mapping, the
    // stop its median.
    double start = parameters.startExposure, stop = parameters.stopExposure;
    if (std::isnan(start) || std::isnan(stop)) {
        const double target = 0.85;
        const double a = kAcesA - target * kAcesD, b = kAcesB - target * kAcesE, c = kAcesC - target * kAcesF;
        const double xt = a == 0 ? -c / b : -0.5 * b / a + std::sqrt(0.25 * b * b / (a * a) - c / a);
        std::vector<double> lum(n);
        double yMax = 0, yMinPositive = std::numeric_limits<double>::infinity();
        for (size_t i = 0; i < n; ++i) {
            lum[i] = 0.2126 * referenceRgb[i].x + 0.7152 * referenceRgb[i].y + 0.0722 * referenceRgb[i].z;
            yMax = std::max(yMax, lum[i]);
            if (lum[i] > 0) yMinPositive = std::min(yMinPositive, lum[i]);
        }
        std::nth_element(lum.begin(), lum.begin() + static_cast<std::ptrdiff_t>(n / 2), lum.end());
        double yMedian = lum[n / 2];
        // A black reference has no range: one exposure, twice. A median of 0
        // (mostly black) stops at the dimmest lit pixel instead of at infinity.
        if (!(yMax > 0)) {
            yMax = 1;
            yMedian = 1;
        } else if (!(yMedian > 0)) {
            yMedian = yMinPositive;
        }
        if (std::isnan(start)) start = std::log2(xt / yMax);
        if (std::isnan(stop)) stop = std::log2(xt / yMedian);
    }
    if (start > stop) throw Error("HDR-FLIP: the start exposure must not exceed the stop exposure");
    const int count = parameters.exposureCount > 0 ? parameters.exposureCount
                                                   : static_cast<int>(std::max(2.0, std::ceil(stop - start)));
    auto expose = [](Vec3 v, double m) {
        auto one = [m](double x) { return std::clamp(Flip::acesToneMap(x * m), 0.0, 1.0); };
        return Vec3{one(v.x), one(v.y), one(v.z)};
    };
    // The exposures are independent: a few threads each take every k-th one
    // and keep their own per-pixel maximum; the maxima are merged (the same
    // result for any thread count).
    const unsigned threads = std::max(
        1u, std::min({std::thread::hardware_concurrency(), 4u, parameters.maxThreads, static_cast<unsigned>(count)}));
    std::vector<std::vector<double>> worstOf(threads, std::vector<double>(n, 0.0));
    std::vector<std::exception_ptr> errors(threads);
    auto work = [&](unsigned t) {
        try {
            std::vector<Vec3> re(n), te(n);
            for (int e = static_cast<int>(t); e < count; e += static_cast<int>(threads)) {
                const double exposure = count == 1 ? start : start + e * (stop - start) / (count - 1);
                const double m = std::exp2(exposure);
                for (size_t i = 0; i < n; ++i) {
                    re[i] = expose(referenceRgb[i], m);
                    te[i] = expose(testRgb[i], m);
                }
                const std::vector<double> ldr = ldrFlipLinear(re, te, w, h, ppd);
                for (size_t i = 0; i < n; ++i) worstOf[t][i] = std::max(worstOf[t][i], ldr[i]);
            }
        } catch (...) {
            errors[t] = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& th : pool) th.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
    std::vector<double>& worst = worstOf[0];
    for (unsigned t = 1; t < threads; ++t)
        for (size_t i = 0; i < n; ++i) worst[i] = std::max(worst[i], worstOf[t][i]);
    FlipResult result = toResult(worst, w, h);
    result.hdr = true;
    result.startExposure = start;
    result.stopExposure = stop;
    result.exposureCount = count;
    result.pixelsPerDegree = ppd;
    return result;
}

}  // namespace dw
