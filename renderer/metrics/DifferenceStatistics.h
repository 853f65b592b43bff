#pragma once
// Absolute-difference statistics of two images of equal shape, through
// OpenImageIO's ImageBufAlgo::compare (OIIO 2.4), over all channels and per
// channel: mean |a-b|, RMS, PSNR, max (and where), and how many pixels have a
// channel over the warn and fail thresholds (idiff's counts).
//
// Shapes: width x height x channels, interleaved, rows top-down (FloatImage).
// Units: the images' own (display values in [0,1] for 8-bit files, radiance
// for an L-buffer). PSNR is OIIO's: 20 log10(1 / RMS) dB, peak 1.0 whatever
// the range (so on HDR values it is a log of the RMS, not a true PSNR);
// +inf when the images are equal.
// Errors: Error when the sizes or channel counts differ (nothing is compared).
#include <string>
#include <vector>

#include "renderer/io/ImageIO.h"

namespace dw {

struct DifferenceFigures {
    double mean = 0, rms = 0, psnr = 0, max = 0;
    int maxX = 0, maxY = 0, maxChannel = 0;  // the largest difference's pixel (rows top-down) and channel
    long long warnCount = 0;  // pixels with a channel's |a-b| > warn threshold
    long long failCount = 0;  // pixels with a channel's |a-b| > fail threshold
};

struct DifferenceStatistics {
    DifferenceFigures overall;
    std::vector<DifferenceFigures> perChannel;  // one per channel (counts: that channel alone)
    long long pixelCount = 0;
    double warnThreshold = 0, failThreshold = 0;

    // Throws Error naming both shapes when they differ.
    static DifferenceStatistics measure(const FloatImage& a, const FloatImage& b, double warnThreshold,
                                        double failThreshold);
    // "WxHxC" as the messages write a shape.
    static std::string shape(const FloatImage& image);
};

}  // namespace dw
