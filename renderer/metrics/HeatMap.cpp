#include "renderer/metrics/HeatMap.h"

#include <cmath>

#include "renderer/Error.h"
#include "shaders/bufferview/turbo.h"

namespace dw {

FloatImage HeatMap::colour(const FloatImage& map, int channel, double low, double high) {
    if (channel < 0 || channel >= map.channels)
        throw Error("heat map: channel " + std::to_string(channel) + " of a " + std::to_string(map.channels) +
                    "-channel map");
    if (!(high > low)) throw Error("heat map: the range's top must exceed its bottom");
    FloatImage out;
    out.width = map.width;
    out.height = map.height;
    out.channels = 3;
    const size_t n = static_cast<size_t>(map.width) * map.height;
    out.pixels.resize(n * 3);
    for (size_t i = 0; i < n; ++i) {
        const double v = map.pixels[i * static_cast<size_t>(map.channels) + static_cast<size_t>(channel)];
        const float t = static_cast<float>(std::isfinite(v) ? (v - low) / (high - low) : 1.0);
        const glm::vec3 c = gpu::turbo(t);
        for (int k = 0; k < 3; ++k) out.pixels[i * 3 + static_cast<size_t>(k)] = std::fmin(std::fmax(c[k], 0.0f), 1.0f);
    }
    return out;
}

}  // namespace dw
