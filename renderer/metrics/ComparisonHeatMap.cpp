#include "renderer/metrics/ComparisonHeatMap.h"

#include <cmath>

#include "renderer/metrics/HeatMap.h"

namespace dw {

double ComparisonHeatMap::top(const ImageComparison& c) {
    if (c.flip) return 1.0;
    return c.difference.overall.max > 0 ? c.difference.overall.max : 1.0;
}

FloatImage ComparisonHeatMap::of(const ImageComparison& c) {
    if (c.flip) return HeatMap::colour(c.flip->map, 0, 0.0, 1.0);
    const FloatImage& m = c.absoluteDifference;
    FloatImage one;
    one.width = m.width;
    one.height = m.height;
    one.channels = 1;
    for (size_t p = 0; p < static_cast<size_t>(m.width) * m.height; ++p) {
        float v = 0;
        for (int k = 0; k < m.channels; ++k) v = std::fmax(v, m.pixels[p * static_cast<size_t>(m.channels) + static_cast<size_t>(k)]);
        one.pixels.push_back(v);
    }
    return HeatMap::colour(one, 0, 0.0, top(c));
}

}  // namespace dw
