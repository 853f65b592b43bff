#pragma once
// Image error over the pixels of a mask only (issue 23: `tradeoff --mask
// shadow_edges`, the error of a shadow study where shadows have edges).
//
// Reads a reference and a test image of the same shape (width x height x
// channels, rows top-down) and a mask width x height x 1 (a pixel counts
// when its value > 0.5; ShadowEdgeMask makes one).
//   rms:      sqrt of the mean over masked pixels and all channels of
//             (a - b)^2: what DifferenceStatistics' RMS (OpenImageIO's) gives
//             over the whole image, restricted to the mask;
//   meanAbs:  the mean |a - b| likewise;
//   psnr:     20 log10(1 / rms) dB (OIIO's peak 1.0), +inf when equal;
//   mapMean:  the mean of a per-pixel map (FLIP's map, SSIM's) over the mask,
//             the map computed on the whole images first (FLIP and SSIM filter
//             across pixels, so they are not computed on the masked pixels
//             alone); a map of several channels: the mean of its channels.
// Errors: Error when the shapes differ (the message names them) or the mask
// holds no pixel ("the mask selects no pixel").
#include "renderer/io/ImageIO.h"

namespace dw {

class MaskedMetrics {
public:
    static double rms(const FloatImage& reference, const FloatImage& test, const FloatImage& mask);
    static double meanAbs(const FloatImage& reference, const FloatImage& test, const FloatImage& mask);
    static double psnr(const FloatImage& reference, const FloatImage& test, const FloatImage& mask);
    static double mapMean(const FloatImage& map, const FloatImage& mask);
};

}  // namespace dw
