#include "renderer/metrics/ImageComparison.h"

#include <cmath>

#include "renderer/Error.h"
#include "renderer/metrics/FinitePixels.h"

namespace dw {

namespace {

// The colour channels SSIM and FLIP read: RGB of RGB(A), or the one channel.
FloatImage colourChannels(const FloatImage& image) {
    if (image.channels <= 3) return image;
    FloatImage out;
    out.width = image.width;
    out.height = image.height;
    out.channels = 3;
    const size_t n = static_cast<size_t>(image.width) * image.height;
    out.pixels.resize(n * 3);
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < 3; ++c) out.pixels[i * 3 + c] = image.pixels[i * static_cast<size_t>(image.channels) + c];
    return out;
}

}  // namespace

ImageComparison ImageComparison::measure(const FloatImage& reference, const FloatImage& test,
                                         const ComparisonSettings& settings, const std::string& referenceName,
                                         const std::string& testName) {
    if (reference.width != test.width || reference.height != test.height || reference.channels != test.channels)
        throw Error("the images differ in shape: " + referenceName + " is " + DifferenceStatistics::shape(reference) +
                    ", " + testName + " is " + DifferenceStatistics::shape(test) + " (width x height x channels)");
    FinitePixels::require(reference, referenceName);
    FinitePixels::require(test, testName);
    ImageComparison c;
    c.hdr = settings.hdr;
    c.difference = DifferenceStatistics::measure(reference, test, settings.warnThreshold, settings.failThreshold);
    c.absoluteDifference = reference;
    for (size_t i = 0; i < c.absoluteDifference.pixels.size(); ++i)
        c.absoluteDifference.pixels[i] = std::fabs(reference.pixels[i] - test.pixels[i]);

    const FloatImage refColour = colourChannels(reference), testColour = colourChannels(test);
    c.ssimEncoding = settings.hdr ? SsimEncoding::Reinhard : SsimEncoding::AsStored;
    SsimParameters ssimParameters;
    const int window = 2 * Ssim::windowRadius(ssimParameters) + 1;
    if (settings.ssim && reference.width >= window && reference.height >= window)
        c.ssim = Ssim::compute(Ssim::encode(refColour, c.ssimEncoding), Ssim::encode(testColour, c.ssimEncoding),
                               ssimParameters);
    else if (settings.ssim)
        c.notes.push_back("no SSIM: the images are smaller than its " + std::to_string(window) + "x" +
                          std::to_string(window) + " window");
    if (settings.flipMetric && (refColour.channels == 1 || refColour.channels == 3))
        c.flip = settings.hdr ? Flip::hdr(refColour, testColour, settings.flip) : Flip::ldr(refColour, testColour, settings.flip);
    else if (settings.flipMetric)
        c.notes.push_back("no FLIP: it needs 1 (grey), 3 or 4 (RGB) channels, the images have " +
                          std::to_string(reference.channels));
    return c;
}

FloatImage ImageComparison::errorMap(std::vector<std::string>& channelNames) const {
    const FloatImage& d = absoluteDifference;
    static const char* kRgba[] = {"R", "G", "B", "A"};
    channelNames.clear();
    auto name = [&](int ch) -> std::string {
        if (d.channels == 1) return "Y";
        if (d.channels == 3 || d.channels == 4) return kRgba[ch];
        return std::to_string(ch);
    };
    for (int ch = 0; ch < d.channels; ++ch) channelNames.push_back("absdiff." + name(ch));
    if (ssim) channelNames.push_back("ssim");
    if (flip) channelNames.push_back("flip");
    FloatImage out;
    out.width = d.width;
    out.height = d.height;
    out.channels = static_cast<int>(channelNames.size());
    const size_t n = static_cast<size_t>(d.width) * d.height;
    out.pixels.resize(n * static_cast<size_t>(out.channels));
    for (size_t i = 0; i < n; ++i) {
        size_t k = i * static_cast<size_t>(out.channels);
        for (int ch = 0; ch < d.channels; ++ch) out.pixels[k++] = d.pixels[i * static_cast<size_t>(d.channels) + static_cast<size_t>(ch)];
        if (ssim) {
            double s = 0;
            for (int ch = 0; ch < ssim->map.channels; ++ch)
                s += ssim->map.pixels[i * static_cast<size_t>(ssim->map.channels) + static_cast<size_t>(ch)];
            out.pixels[k++] = static_cast<float>(s / ssim->map.channels);
        }
        if (flip) out.pixels[k++] = flip->map.pixels[i];
    }
    return out;
}

}  // namespace dw
