#include "renderer/metrics/FinitePixels.h"

#include <cmath>

#include "renderer/Error.h"

namespace dw {

void FinitePixels::require(const FloatImage& image, const std::string& name) {
    long long bad = 0;
    size_t first = image.pixels.size();
    for (size_t i = 0; i < image.pixels.size(); ++i)
        if (!std::isfinite(image.pixels[i])) {
            if (bad++ == 0) first = i;
        }
    if (bad == 0) return;
    const float v = image.pixels[first];
    const size_t channels = static_cast<size_t>(image.channels);
    const size_t pixel = first / channels;
    const int x = static_cast<int>(pixel % static_cast<size_t>(image.width));
    const int y = static_cast<int>(pixel / static_cast<size_t>(image.width));
    const std::string what = std::isnan(v) ? "NaN" : (v > 0 ? "+inf" : "-inf");
    throw Error(name + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                std::to_string(first % channels) + " is " + what + " (" + std::to_string(bad) +
                " non-finite values in all); metrics need finite pixels");
}

}  // namespace dw
