#pragma once
// Every metric of one image pair, computed once: the absolute-difference
// statistics (OpenImageIO), SSIM and FLIP, and the per-pixel error maps.
// What `compare` prints and writes, and what the gates judge.
//
// The pair is a reference and a test of the same shape (width x height x
// channels, rows top-down), either
//   LDR: display values in [0, 1] (8-bit files / 255, sRGB-encoded): SSIM on
//        the values as stored, data range 1; LDR-FLIP;
//   HDR: linear radiance (EXR, the L-buffer): SSIM on Reinhard-encoded values
//        v / (1 + v) per channel (SsimEncoding::Reinhard), data range 1;
//        HDR-FLIP.
// SSIM and FLIP read the colour channels: the first three of an RGB(A) image
// (alpha left out), the one of a grey image; the difference statistics read
// every channel. SSIM needs at least 11 x 11 pixels and FLIP 1, 3 or 4
// channels: otherwise that metric is absent (std::nullopt) and `notes` says why.
// Errors: Error when the shapes differ (the message names both), or a pixel is
// not finite (FinitePixels: which image, which pixel).
#include <optional>
#include <string>
#include <vector>

#include "renderer/io/ImageIO.h"
#include "renderer/metrics/DifferenceStatistics.h"
#include "renderer/metrics/Flip.h"
#include "renderer/metrics/Ssim.h"

namespace dw {

struct ComparisonSettings {
    bool hdr = false;
    double warnThreshold = 1e-6;  // per-channel |a - b| (idiff's default)
    double failThreshold = 1e-6;
    FlipParameters flip;
    // SSIM and FLIP cost far more than the difference statistics: a caller
    // that needs one metric (tradeoff) leaves the others out (absent, no note).
    bool ssim = true, flipMetric = true;
};

struct ImageComparison {
    bool hdr = false;
    DifferenceStatistics difference;
    std::optional<SsimResult> ssim;
    SsimEncoding ssimEncoding = SsimEncoding::AsStored;
    std::optional<FlipResult> flip;
    std::vector<std::string> notes;  // why a metric is absent
    FloatImage absoluteDifference;   // |reference - test| per channel, same shape as the inputs

    // `referenceName`, `testName`: how errors name the images (file names).
    static ImageComparison measure(const FloatImage& reference, const FloatImage& test,
                                   const ComparisonSettings& settings, const std::string& referenceName = "reference",
                                   const std::string& testName = "test");

    // One EXR-ready image of every map: the absolute difference's channels,
    // then "ssim" (the mean over the SSIM channels, 1 - identical) and "flip"
    // where computed. Names in `channelNames`.
    FloatImage errorMap(std::vector<std::string>& channelNames) const;
};

}  // namespace dw
