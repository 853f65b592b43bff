#include "renderer/metrics/ShadowEdgeMask.h"

#include <algorithm>

#include "renderer/Error.h"

namespace dw {

namespace {

FloatImage blank(int w, int h) {
    FloatImage out;
    out.width = w;
    out.height = h;
    out.channels = 1;
    out.pixels.assign(static_cast<size_t>(w) * static_cast<size_t>(h), 0.0f);
    return out;
}

}  // namespace

FloatImage ShadowEdgeMask::fromShadow(const FloatImage& shadow, const ShadowEdgeSettings& settings) {
    if (shadow.channels != 1)
        throw Error("the shadow-edge mask needs a one-channel shadow buffer, this one has " +
                    std::to_string(shadow.channels) + " channels");
    if (shadow.width <= 0 || shadow.height <= 0) throw Error("the shadow-edge mask needs a non-empty shadow buffer");
    if (settings.dilation < 0) throw Error("the shadow-edge mask's dilation must be >= 0 pixels");
    const int w = shadow.width, h = shadow.height;
    FloatImage edges = blank(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float lo = shadow.at(x, y, 0), hi = lo;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const float v = shadow.at(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1), 0);
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
            if (hi - lo > settings.contrast) edges.at(x, y, 0) = 1.0f;
        }
    // Square dilation, separable: rows then columns.
    const int r = settings.dilation;
    FloatImage rows = blank(w, h), out = blank(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int dx = std::max(0, x - r); dx <= std::min(w - 1, x + r); ++dx)
                if (edges.at(dx, y, 0) > 0.5f) {
                    rows.at(x, y, 0) = 1.0f;
                    break;
                }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int dy = std::max(0, y - r); dy <= std::min(h - 1, y + r); ++dy)
                if (rows.at(x, dy, 0) > 0.5f) {
                    out.at(x, y, 0) = 1.0f;
                    break;
                }
    return out;
}

long long ShadowEdgeMask::count(const FloatImage& mask) {
    long long n = 0;
    for (size_t i = 0; i < mask.pixels.size(); i += static_cast<size_t>(std::max(1, mask.channels)))
        if (mask.pixels[i] > 0.5f) ++n;
    return n;
}

}  // namespace dw
