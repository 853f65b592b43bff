#include "renderer/reference/ToneMapReference.h"

#include <algorithm>
#include <cmath>

#include "renderer/reference/LuminanceReference.h"
#include "renderer/reference/TextureSampler.h"

namespace dw::reference {

namespace {

glm::dvec3 guard(glm::dvec3 c) {
    for (int i = 0; i < 3; ++i) c[i] = std::isnan(c[i]) ? 0.0 : std::clamp(c[i], 0.0, 1e38);
    return c;
}

glm::dvec3 acesFitted(const glm::dvec3& c) {
    const glm::dmat3 inputMat(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777);
    const glm::dmat3 outputMat(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602);
    const glm::dvec3 v = inputMat * c;
    const glm::dvec3 a = v * (v + 0.0245786) - 0.000090537;
    const glm::dvec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return glm::clamp(outputMat * (a / b), 0.0, 1.0);
}

glm::dvec3 pbrNeutral(glm::dvec3 color) {
    const double startCompression = 0.8 - 0.04, desaturation = 0.15;
    const double x = std::min(color.r, std::min(color.g, color.b));
    const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    const double peak = std::max(color.r, std::max(color.g, color.b));
    if (peak < startCompression) return color;
    const double d = 1.0 - startCompression;
    const double newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    const double g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return glm::mix(color, glm::dvec3(newPeak), g);
}

}  // namespace

ToneStatistics toneStatistics(const FloatImage& lbuffer, const std::vector<std::uint8_t>& background,
                              const ReferenceModel& model) {
    double sumLog = 0.0;
    long long count = 0;
    ToneStatistics s;
    const size_t n = static_cast<size_t>(lbuffer.width) * lbuffer.height;
    for (size_t p = 0; p < n; ++p) {
        if (!model.backgroundInStatistics && !background.empty() && background[p]) continue;
        const float* px = &lbuffer.pixels[p * lbuffer.channels];
        if (!std::isfinite(px[0]) || !std::isfinite(px[1]) || !std::isfinite(px[2])) continue;
        const double L = std::max(luminance(px[0], px[1], px[2]), 0.0);
        sumLog += std::log(model.logDelta + L);
        s.maxLuminance = std::max(s.maxLuminance, L);
        ++count;
    }
    s.measured = count > 0 && s.maxLuminance > 0.0;
    s.logAverage = s.measured ? std::exp(sumLog / static_cast<double>(count)) : 1.0;
    return s;
}

glm::dvec3 toneMapPixel(glm::dvec3 hdr, const ToneStatistics& stats, const ReferenceModel& m) {
    if (m.nanGuard) hdr = guard(hdr);
    double scale = std::exp2(m.exposure);
    if (m.toneOperator == ToneOperator::Reinhard || m.autoExposure) scale *= m.key / std::max(stats.logAverage, 1e-9);
    hdr *= scale;
    switch (m.toneOperator) {
        case ToneOperator::Aces: return acesFitted(hdr);
        case ToneOperator::Neutral: return glm::clamp(pbrNeutral(hdr), 0.0, 1.0);
        case ToneOperator::Clamp: return glm::clamp(hdr, 0.0, 1.0);
        default: break;
    }
    const double L = luminance(hdr.r, hdr.g, hdr.b);
    double ratio;
    if (m.toneOperator == ToneOperator::Reinhard) {
        double white = m.autoWhite && stats.measured ? scale * stats.maxLuminance : m.white;
        white = std::max(white, 1e-6);
        ratio = (1.0 + L / (white * white)) / (1.0 + L);
    } else {
        ratio = 1.0 / (1.0 + L);
    }
    return L > 0.0 ? glm::clamp(hdr * std::min(ratio, 1e30), 0.0, 1.0) : glm::dvec3(0.0);
}

FloatImage toneMap(const FloatImage& lbuffer, const std::vector<std::uint8_t>& background, const ReferenceModel& model) {
    const ToneStatistics stats = toneStatistics(lbuffer, background, model);
    FloatImage out;
    out.width = lbuffer.width;
    out.height = lbuffer.height;
    out.channels = 4;
    out.pixels.resize(static_cast<size_t>(out.width) * out.height * 4);
    const size_t n = static_cast<size_t>(out.width) * out.height;
    for (size_t p = 0; p < n; ++p) {
        const float* px = &lbuffer.pixels[p * lbuffer.channels];
        glm::dvec3 c = toneMapPixel({px[0], px[1], px[2]}, stats, model);
        for (int i = 0; i < 3; ++i) {
            const double v = std::clamp(c[i], 0.0, 1.0);
            out.pixels[p * 4 + i] = static_cast<float>(model.srgb ? linearToSrgb(v) : v);
        }
        out.pixels[p * 4 + 3] = 1.0f;
    }
    return out;
}

}  // namespace dw::reference
