#pragma once
// Refuses an image holding a NaN or an infinity before any metric reads it:
// every statistic of such an image is NaN or meaningless, and the first bad
// pixel is what the user needs to find the pass (or file) that made it.
#include <string>

#include "renderer/io/ImageIO.h"

namespace dw {

class FinitePixels {
public:
    // Throws Error("<name>: pixel (x, y) channel c is NaN|+inf|-inf (N non-finite values in all)"),
    // (x, y) in image coordinates, rows top-down, for the first such value in row order.
    static void require(const FloatImage& image, const std::string& name);
};

}  // namespace dw
