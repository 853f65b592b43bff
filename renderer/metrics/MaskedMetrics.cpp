#include "renderer/metrics/MaskedMetrics.h"

#include <cmath>
#include <limits>

#include "renderer/Error.h"
#include "renderer/metrics/DifferenceStatistics.h"

namespace dw {

namespace {

void requireMask(const FloatImage& image, const FloatImage& mask) {
    if (mask.channels != 1 || mask.width != image.width || mask.height != image.height)
        throw Error("the mask is " + DifferenceStatistics::shape(mask) + ", the image " +
                    DifferenceStatistics::shape(image) + ": a mask is the image's width x height x 1");
}

void requirePair(const FloatImage& a, const FloatImage& b, const FloatImage& mask) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        throw Error("the images differ in shape (" + DifferenceStatistics::shape(a) + " vs " +
                    DifferenceStatistics::shape(b) + ", width x height x channels)");
    requireMask(a, mask);
}

// Sum over masked pixels of |a-b|^power per channel, and the count of values.
std::pair<double, long long> maskedSum(const FloatImage& a, const FloatImage& b, const FloatImage& mask, int power) {
    requirePair(a, b, mask);
    double sum = 0;
    long long n = 0;
    const size_t pixels = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
    const size_t c = static_cast<size_t>(a.channels);
    for (size_t i = 0; i < pixels; ++i) {
        if (!(mask.pixels[i] > 0.5f)) continue;
        for (size_t k = 0; k < c; ++k) {
            const double d = std::fabs(static_cast<double>(a.pixels[i * c + k]) - b.pixels[i * c + k]);
            sum += power == 2 ? d * d : d;
            ++n;
        }
    }
    if (n == 0) throw Error("the mask selects no pixel");
    return {sum, n};
}

}  // namespace

double MaskedMetrics::rms(const FloatImage& reference, const FloatImage& test, const FloatImage& mask) {
    const auto [sum, n] = maskedSum(reference, test, mask, 2);
    return std::sqrt(sum / static_cast<double>(n));
}

double MaskedMetrics::meanAbs(const FloatImage& reference, const FloatImage& test, const FloatImage& mask) {
    const auto [sum, n] = maskedSum(reference, test, mask, 1);
    return sum / static_cast<double>(n);
}

double MaskedMetrics::psnr(const FloatImage& reference, const FloatImage& test, const FloatImage& mask) {
    const double e = rms(reference, test, mask);
    return e > 0 ? 20.0 * std::log10(1.0 / e) : std::numeric_limits<double>::infinity();
}

double MaskedMetrics::mapMean(const FloatImage& map, const FloatImage& mask) {
    requireMask(map, mask);
    double sum = 0;
    long long n = 0;
    const size_t pixels = static_cast<size_t>(map.width) * static_cast<size_t>(map.height);
    const size_t c = static_cast<size_t>(map.channels);
    for (size_t i = 0; i < pixels; ++i) {
        if (!(mask.pixels[i] > 0.5f)) continue;
        double s = 0;
        for (size_t k = 0; k < c; ++k) s += map.pixels[i * c + k];
        sum += s / static_cast<double>(c);
        ++n;
    }
    if (n == 0) throw Error("the mask selects no pixel");
    return sum / static_cast<double>(n);
}

}  // namespace dw
