#pragma once
// The temporal error of an image sequence against a reference sequence
// (issue 35 part 4): how far the test's frame-to-frame change is from the
// reference's. A method can be right on average in every frame and still
// flicker (change the reference does not have), and a temporal method can
// trade that flicker for ghosting or lag (change the reference has that the
// test lacks); this number measures both and nothing else.
//
// Definition (docs/metrics.md, "Temporal error"): frames t = 0..T-1 of
// equal shape, T >= 2; on each pixel's luminance Y = 0.2126 R + 0.7152 G +
// 0.0722 B (Rec. 709 weights on the values as given: linear light for HDR
// buffers, luma of display values for `final`; a one- or two-channel image
// uses its first channel), the test's change d_t = Y(I_t) - Y(I_{t-1}) and the
// reference's r_t = Y(R_t) - Y(R_{t-1}), t = 1..T-1. Per frame pair, e_t = the
// mean over pixels of |d_t - r_t|; the temporal error is the mean of e_t over
// the T-1 pairs, in the images' units (display values 0-1 for `final`), with a
// 95% percentile bootstrap interval over frame pairs (Bootstrap.h,
// bootstrapGroupMean, each pair weight 1). 0 exactly when the test changes as
// the reference does (a still camera on a static scene: both changes 0); a
// constant offset between test and reference cancels. The idea is the
// "temporal stability" comparison of frame differences used to evaluate TAA
// (e.g. Yang, Liu, Salvi, "A Survey of Temporal Antialiasing Techniques",
// Eurographics STAR 2020, section 7), written here as above.
// Needs no GL.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/io/ImageIO.h"
#include "renderer/metrics/Bootstrap.h"

namespace dw {

struct TemporalErrorResult {
    std::vector<double> pairs;  // e_t for t = 1..T-1 (pairs[0] is frames 0 -> 1)
    double mean = 0.0;          // the mean of `pairs`
    Interval interval;          // its 95% bootstrap interval over the pairs
};

class TemporalError {
public:
    // The luminance the definition reads of pixel (x, y).
    static double luminance(const FloatImage& image, int x, int y);
    // Throws Error, naming the frame ("test frame 3: ..."), when the sequences
    // differ in length or hold fewer than 2 frames, when a frame's shape
    // (width x height x channels) differs from reference frame 0's, or when a
    // frame holds a NaN or an infinity (FinitePixels).
    static TemporalErrorResult measure(const std::vector<FloatImage>& reference, const std::vector<FloatImage>& test,
                                       int resamples = 2000, std::uint64_t seed = 12345);
};

}  // namespace dw
