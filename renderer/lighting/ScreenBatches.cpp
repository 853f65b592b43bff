#include "renderer/lighting/ScreenBatches.h"

#include <algorithm>
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
    const int words = (cols * rows + 63) / 64;
    std::vector<std::vector<std::uint64_t>> used;  // per batch, one bit per cell
    auto cellsOf = [&](const PixelRect& r, auto&& visit) {
        for (int cy = r.y0 / cell; cy <= (r.y1 - 1) / cell; ++cy)
            for (int cx = r.x0 / cell; cx <= (r.x1 - 1) / cell; ++cx)
                if (!visit(cy * cols + cx)) return false;
        return true;
    };
    for (std::size_t i = 0; i < rects.size(); ++i) {
        const PixelRect& r = rects[i];
        if (r.empty()) continue;
        std::size_t b = 0;
        for (; b < used.size(); ++b) {
            std::vector<std::uint64_t>& bits = used[b];
            if (cellsOf(r, [&](int c) { return (bits[static_cast<std::size_t>(c / 64)] >> (c % 64) & 1u) == 0; })) break;
        }
        if (b == used.size()) used.emplace_back(static_cast<std::size_t>(words), 0u);
        std::vector<std::uint64_t>& bits = used[b];
        cellsOf(r, [&](int c) {
            bits[static_cast<std::size_t>(c / 64)] |= std::uint64_t{1} << (c % 64);
            return true;
        });
        batchOf[i] = static_cast<int>(b);
    }
    return batchOf;
}

}  // namespace dw
