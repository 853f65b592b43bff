#pragma once
// Log-average and max luminance of an HDR image in double precision (seed 000
// eq. 4.2), the ground truth for the GPU reduction in LuminancePass.
#include "renderer/io/ImageIO.h"

namespace dw::reference {

struct LuminanceStats {
    double logAverage = 0.0;
    double max = 0.0;
    double mean = 0.0;
    long long finiteCount = 0;
};

double luminance(double r, double g, double b);
// Pixels with a NaN or infinite channel are skipped, as on the GPU. With no
// pixel left, or only black ones, logAverage is 1 (a neutral exposure).
LuminanceStats luminanceStats(const FloatImage& image, double delta);

}  // namespace dw::reference
