#pragma once
// One number for how far a test image is from a reference, with an interval:
// `tradeoff`'s error column. The metric is one of compare's (renderer/metrics:
// ImageComparison), on the images as compare takes them (HDR: linear
// buffers such as the L-buffer and the AO; LDR: the final image):
//   rms   sqrt of the mean over pixels and channels of (reference - test)^2
//   psnr  OpenImageIO's, as compare prints it (larger is better)
//   flip  the mean of the FLIP map (LDR- or HDR-FLIP)
//   ssim  the mean SSIM (larger is better)
// The interval is a percentile bootstrap over 16x16-pixel tiles (whole tiles
// are resampled, so neighbouring pixels' correlated errors stay together):
// the per-pixel quantity behind the metric (squared difference, FLIP value,
// SSIM value) is summed per tile, tiles are drawn with replacement, and the
// metric is recomputed from the drawn tiles' mean (for ssim the interval is
// of the map's mean, moved to sit about the reported mean).
// Needs no GL.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/io/ImageIO.h"

namespace dw {

// The per-tile sums behind an estimate, kept so that two estimates can be
// compared on the same resampled tiles (ConfidentFront's paired bootstrap):
// tile t holds sums[t] (the summed per-pixel quantity) over counts[t] pixels,
// and valueOf(S, N) is the metric of tiles whose sums add up to S over N
// pixels: rms sqrt(S/N), psnr 10 log10(peak2 / (S/N)), flip S/N, ssim S/N +
// shift (the map's mean moved to the reported mean). Empty: none kept.
struct ErrorTiles {
    std::string metric;
    std::vector<double> sums, counts;
    double peak2 = 1.0, shift = 0.0;
    double valueOf(double sum, double count) const;
};

struct ErrorEstimate {
    double value = 0.0, low = 0.0, high = 0.0;  // NaN: not measured
    ErrorTiles tiles;                           // measure()'s; none from meanOver()
};

class ImageError {
public:
    static constexpr int kTile = 16;
    // The metrics known: flip, rms, psnr, ssim.
    static const std::vector<std::string>& metrics();
    // Throws Error for an unknown metric, images of different shapes, a
    // non-finite pixel, or a metric the images cannot have (SSIM under 11x11).
    // With `mask` (width x height x 1, a pixel counts when > 0.5: ShadowEdgeMask),
    // the metric over the masked pixels only (MaskedMetrics: rms and psnr from
    // the masked pixels' squared differences, flip and ssim the mean of their
    // map over the mask) and the tiles' sums over their masked pixels; Error
    // when the mask's shape differs or it selects no pixel.
    static ErrorEstimate measure(const FloatImage& reference, const FloatImage& test, const std::string& metric, bool hdr,
                                 int resamples = 2000, std::uint64_t seed = 12345, const FloatImage* mask = nullptr);
    // The mean of per-camera errors with a percentile bootstrap over the
    // cameras that have one: NaN values (a camera without an error) are left
    // out; all NaN (or none given) gives NaN. A mean that is infinite (a PSNR
    // of inf on a camera) has no interval (NaN low and high).
    static ErrorEstimate meanOver(const std::vector<double>& values, int resamples = 2000, std::uint64_t seed = 12345);
};

}  // namespace dw
