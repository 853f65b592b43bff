#include "renderer/lighting/ScreenBatches.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace dw {

PixelRect screenRect(const glm::dmat4& localToClip, const glm::vec3& boxMin, const glm::vec3& boxMax, int width,
                     int height) {
    const PixelRect whole{0, 0, width, height};
    double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 corner((i & 1) ? boxMax.x : boxMin.x, (i & 2) ? boxMax.y : boxMin.y, (i & 4) ? boxMax.z : boxMin.z,
                                1.0);
        const glm::dvec4 c = localToClip * corner;
        if (!(c.w > 1e-9)) return whole;
        const double x = (c.x / c.w * 0.5 + 0.5) * width, y = (c.y / c.w * 0.5 + 0.5) * height;
        if (!std::isfinite(x) || !std::isfinite(y)) return whole;
        minX = std::min(minX, x);
        maxX = std::max(maxX, x);
        minY = std::min(minY, y);
        maxY = std::max(maxY, y);
    }
    auto clampTo = [](double v, int hi) { return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi))); };
    return {clampTo(std::floor(minX) - 1.0, width), clampTo(std::floor(minY) - 1.0, height),
            clampTo(std::ceil(maxX) + 1.0, width), clampTo(std::ceil(maxY) + 1.0, height)};
}

std::vector<int> disjointBatches(const std::vector<PixelRect>& rects, int width, int height) {
    std::vector<int> batchOf(rects.size(), 0);
    if (width <= 0 || height <= 0) return batchOf;
    const int cell = std::max({1, (width + 63) / 64, (height + 63) / 64});
    const int cols = (width + cell - 1) / cell, rows = (height + cell - 1) / cell;
    // Per cell, one bit per batch that holds a rectangle over it, in words
    // of 64 batches; `words` grows (and the table is laid out again) when the
    // batches outgrow it. First fit is then the lowest bit that is clear in
    // every cell of the rectangle, looked for a word at a time.
    std::size_t words = 1;
    std::vector<std::uint64_t> used(static_cast<std::size_t>(cols * rows) * words, 0u);
    int batches = 0;
    for (std::size_t i = 0; i < rects.size(); ++i) {
        const PixelRect& r = rects[i];
        if (r.empty()) continue;
        const int cx0 = r.x0 / cell, cx1 = (r.x1 - 1) / cell, cy0 = r.y0 / cell, cy1 = (r.y1 - 1) / cell;
        int b = -1;
        for (std::size_t w = 0; b < 0; ++w) {
            if (w == words) {  // every batch so far meets the rectangle: a new one
                b = batches;
                break;
            }
            std::uint64_t taken = 0;
            for (int cy = cy0; cy <= cy1 && taken != ~std::uint64_t{0}; ++cy)
                for (int cx = cx0; cx <= cx1; ++cx) taken |= used[static_cast<std::size_t>(cy * cols + cx) * words + w];
            if (taken != ~std::uint64_t{0}) b = static_cast<int>(w * 64) + std::countr_one(taken);
        }
        b = std::min(b, batches);  // a clear bit past the last batch is a new batch
        if (b == batches) {
            ++batches;
            if (static_cast<std::size_t>(batches) > words * 64) {
                std::vector<std::uint64_t> wider(static_cast<std::size_t>(cols * rows) * words * 2, 0u);
                for (std::size_t c = 0; c < static_cast<std::size_t>(cols * rows); ++c)
                    std::copy_n(used.begin() + static_cast<std::ptrdiff_t>(c * words), words,
                                wider.begin() + static_cast<std::ptrdiff_t>(c * words * 2));
                used.swap(wider);
                words *= 2;
            }
        }
        const std::size_t w = static_cast<std::size_t>(b) / 64;
        const std::uint64_t bit = std::uint64_t{1} << (b % 64);
        for (int cy = cy0; cy <= cy1; ++cy)
            for (int cx = cx0; cx <= cx1; ++cx) used[static_cast<std::size_t>(cy * cols + cx) * words + w] |= bit;
        batchOf[i] = b;
    }
    return batchOf;
}

}  // namespace dw
