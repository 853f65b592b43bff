#pragma once
// FLIP, the perceptual difference of an image pair as a viewer flipping
// between them sees it, written from the papers:
//   LDR-FLIP: Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom,
//     Fairchild, "FLIP: A Difference Evaluator for Alternating Images",
//     Proc. ACM Comput. Graph. Interact. Tech. 3(2) (HPG 2020);
//   HDR-FLIP: Andersson, Nilsson, Shirley, Akenine-Moller, "Visualizing
//     Errors in Rendered High Dynamic Range Images", Eurographics 2021 (short).
// The authors' code (github.com/NVlabs/flip) was read for its constants and
// boundary handling, not copied.
//
// LDR-FLIP, per pixel, for a reference and a test image in [0, 1]:
//  colour  sRGB -> linear RGB -> XYZ (D65) -> YCxCz (linearised CIELAB:
//          Y = 116 y/yn - 16, Cx = 500 (x/xn - y/yn), Cz = 200 (y/yn - z/zn));
//          each channel filtered by its contrast sensitivity function as a
//          spatial kernel  a sqrt(pi/b) exp(-pi^2 r^2 / b),  r in degrees
//          (pixels / pixelsPerDegree): Y a=1 b=0.0047; Cx a=1 b=0.0053; Cz the
//          sum of a=34.1 b=0.04 and a=13.5 b=0.025; each kernel normalised to
//          sum 1, radius ceil(3 sqrt(0.04 / (2 pi^2)) ppd); edge pixels
//          repeated outside the image; back to linear RGB clamped to [0, 1],
//          then CIELAB with the Hunt adjustment (a, b scaled by 0.01 L);
//          HyAB distance |dL| + sqrt(da^2 + db^2), raised to qc = 0.7, and
//          mapped to [0, 1]: below pc cmax (pc = 0.4) linearly to [0, pt]
//          (pt = 0.95), above it linearly from pt to 1 at cmax, where cmax is
//          the HyAB distance of Hunt-adjusted green and blue to the power qc;
//  feature on the achromatic channel (Y + 16) / 116 in [0, 1]: edges (first
//          derivative of a Gaussian) and points (second derivative), sigma =
//          0.5 w ppd with w = 0.082 degrees, radius ceil(3 sigma); each
//          derivative kernel normalised so its positive weights sum to 1 and
//          its negative ones to -1; the magnitudes |(dx, dy)| of each image;
//          feature difference = (max(|edge_r - edge_t|, |point_r - point_t|)
//          / sqrt 2)^qf, qf = 0.5;
//  FLIP = colour difference ^ (1 - feature difference), in [0, 1].
// HDR-FLIP for linear radiance: exposures from the reference (start = log2(
// x_t / Y_max), stop = log2(x_t / Y_median), Y the luminance 0.2126 R +
// 0.7152 G + 0.0722 B, x_t where the ACES fit below reaches 0.85), a number of
// exposures max(2, ceil(stop - start)) evenly spaced; at each exposure e both
// images times 2^e, tone mapped by the ACES fit (Narkowicz 2015, with its 0.6
// pre-exposure folded in) and clamped to [0, 1], LDR-FLIP of those as linear
// values; the per-pixel maximum over exposures.
//
// Shapes: reference and test width x height x channels (3 or 4: RGB read, any
// alpha ignored; 1: grey), rows top-down; the map is width x height x 1.
// Units: FLIP is dimensionless in [0, 1] (0: no visible difference).
// Pixels per degree: the viewing condition, default 67.02 (0.7 m from a
// 0.7 m wide 3840-pixel monitor).
// Errors: Error when the shapes differ or have 2 channels.
#include <limits>

#include "renderer/io/ImageIO.h"

namespace dw {

struct FlipParameters {
    double pixelsPerDegree = 0;  // 0: the default viewing condition (pixelsPerDegree(0.7, 3840, 0.7)); else 1..1000 (limits::kPixelsPerDegree), Error outside
    // HDR-FLIP only: the exposure range (stops); NaN: from the reference, as above.
    double startExposure = std::numeric_limits<double>::quiet_NaN();
    double stopExposure = std::numeric_limits<double>::quiet_NaN();
    int exposureCount = 0;  // 0: max(2, ceil(stop - start))
    // HDR-FLIP: how many exposures are evaluated at once (threads, at most 4;
    // each holds about kBytesPerEvaluation per pixel): a caller bounded in
    // memory (compare, DW_IMAGE_LIMIT_MB) asks for fewer. The result is the
    // same for any number.
    unsigned maxThreads = 4;
    static constexpr double kBytesPerEvaluation = 270;  // measured: docs/metrics.md
};

struct FlipResult {
    double mean = 0;  // the map's mean
    FloatImage map;   // width x height x 1, in [0, 1]
    bool hdr = false;
    // HDR-FLIP: the exposures used.
    double startExposure = 0, stopExposure = 0;
    int exposureCount = 0;
    double pixelsPerDegree = 0;
};

class Flip {
public:
    // Both images sRGB-encoded display values in [0, 1] (clamped).
    static FlipResult ldr(const FloatImage& reference, const FloatImage& test, const FlipParameters& parameters = {});
    // Both images linear RGB radiance (negative values are clamped to 0 by the tone mapping's clamp).
    static FlipResult hdr(const FloatImage& reference, const FloatImage& test, const FlipParameters& parameters = {});
    // Pixels per degree of visual angle for a viewer `distance` metres from a
    // monitor `monitorWidth` metres wide showing `resolutionX` pixels across:
    // distance (resolutionX / monitorWidth) pi / 180.
    static double pixelsPerDegree(double distance, double resolutionX, double monitorWidth);
    static double defaultPixelsPerDegree() { return pixelsPerDegree(0.7, 3840.0, 0.7); }
    // The ACES filmic fit HDR-FLIP tone maps with, per channel, unclamped.
    static double acesToneMap(double x);
};

}  // namespace dw
