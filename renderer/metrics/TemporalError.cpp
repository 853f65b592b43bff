#include "renderer/metrics/TemporalError.h"

#include <cmath>
#include <cstdlib>

#include "renderer/Error.h"
#include "renderer/metrics/FinitePixels.h"

namespace dw {

namespace {

std::string shapeText(const FloatImage& f) {
    return std::to_string(f.width) + "x" + std::to_string(f.height) + "x" + std::to_string(f.channels);
}

// Every frame of both sequences the shape of reference frame 0, and finite.
void checkSequences(const std::vector<FloatImage>& reference, const std::vector<FloatImage>& test) {
    if (reference.size() != test.size())
        throw Error("temporal error: the reference has " + std::to_string(reference.size()) + " frames, the test " +
                    std::to_string(test.size()) + "; the sequences must have as many");
    if (reference.size() < 2)
        throw Error("temporal error: needs at least 2 frames (one frame-to-frame change); got " +
                    std::to_string(reference.size()));
    const FloatImage& first = reference.front();
    if (first.width <= 0 || first.height <= 0 || first.channels <= 0) throw Error("temporal error: reference frame 0 is empty");
    for (const auto* side : {&reference, &test}) {
        const std::string name = side == &reference ? "reference frame " : "test frame ";
        for (size_t t = 0; t < side->size(); ++t) {
            const FloatImage& f = (*side)[t];
            if (f.width != first.width || f.height != first.height || f.channels != first.channels)
                throw Error("temporal error: " + name + std::to_string(t) + " is " + shapeText(f) +
                            ", reference frame 0 is " + shapeText(first) + "; every frame must have one shape");
            FinitePixels::require(f, name + std::to_string(t));
        }
    }
}

std::vector<double> luminanceOf(const FloatImage& f) {
    std::vector<double> y(static_cast<size_t>(f.width) * static_cast<size_t>(f.height));
    for (int py = 0; py < f.height; ++py)
        for (int px = 0; px < f.width; ++px)
            y[static_cast<size_t>(py) * static_cast<size_t>(f.width) + static_cast<size_t>(px)] =
                TemporalError::luminance(f, px, py);
    return y;
}

}  // namespace

double TemporalError::luminance(const FloatImage& image, int x, int y) {
    if (image.channels < 3) return image.at(x, y, 0);
    return 0.2126 * image.at(x, y, 0) + 0.7152 * image.at(x, y, 1) + 0.0722 * image.at(x, y, 2);
}

TemporalErrorResult TemporalError::measure(const std::vector<FloatImage>& reference,
                                           const std::vector<FloatImage>& test, int resamples, std::uint64_t seed) {
    checkSequences(reference, test);
    TemporalErrorResult result;
    std::vector<double> refPrev = luminanceOf(reference[0]), testPrev = luminanceOf(test[0]);
    for (size_t t = 1; t < reference.size(); ++t) {
        const std::vector<double> refNow = luminanceOf(reference[t]), testNow = luminanceOf(test[t]);
        double sum = 0.0;
        for (size_t p = 0; p < refNow.size(); ++p)
            sum += std::fabs((testNow[p] - testPrev[p]) - (refNow[p] - refPrev[p]));
        result.pairs.push_back(sum / static_cast<double>(refNow.size()));
        refPrev = refNow;
        testPrev = testNow;
    }
    double total = 0.0;
    for (double e : result.pairs) total += e;
    result.mean = total / static_cast<double>(result.pairs.size());
    result.interval =
        bootstrapGroupMean(result.pairs, std::vector<double>(result.pairs.size(), 1.0), resamples, seed);
    return result;
}

}  // namespace dw
