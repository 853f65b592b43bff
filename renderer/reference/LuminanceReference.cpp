#include "renderer/reference/LuminanceReference.h"

#include <algorithm>
#include <cmath>

namespace dw::reference {

double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }

LuminanceStats luminanceStats(const FloatImage& image, double delta) {
    LuminanceStats s;
    double sumLog = 0.0, sum = 0.0;
    const size_t n = static_cast<size_t>(image.width) * image.height;
    for (size_t p = 0; p < n; ++p) {
        const float* px = &image.pixels[p * image.channels];
        if (!std::isfinite(px[0]) || !std::isfinite(px[1]) || !std::isfinite(px[2])) continue;
        const double L = std::max(luminance(px[0], px[1], px[2]), 0.0);
        sumLog += std::log(delta + L);
        sum += L;
        s.max = std::max(s.max, L);
        ++s.finiteCount;
    }
    if (s.finiteCount > 0) s.mean = sum / static_cast<double>(s.finiteCount);
    // Nothing counted, or only black: the defined fallback, as on the GPU.
    s.logAverage = s.finiteCount > 0 && s.max > 0.0 ? std::exp(sumLog / static_cast<double>(s.finiteCount)) : 1.0;
    return s;
}

}  // namespace dw::reference
