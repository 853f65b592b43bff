// Issue 35 part 4: the temporal error (renderer/metrics/TemporalError.h) on a
// case whose answer is known in closed form: a vertical step edge moving a
// quarter of a pixel per frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/Error.h"
#include "renderer/metrics/TemporalError.h"

namespace dw {
namespace {

constexpr int kW = 16, kH = 2, kFrames = 17;  // 16 frame pairs, four whole cycles of the edge's phase

// The edge's position in pixels at frame t: bright (1) left of it, dark (0)
// right of it; pixel i covers [i, i + 1).
double edgeAt(int t) { return 2.125 + 0.25 * t; }

// The truth of a pixel is its area's mean (a box filter): the part of [i, i + 1) left of the edge.
FloatImage boxFiltered(int t, int channels = 1) {
    FloatImage f{kW, kH, channels, std::vector<float>(static_cast<size_t>(kW * kH * channels))};
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            for (int c = 0; c < channels; ++c) f.at(x, y, c) = static_cast<float>(std::clamp(edgeAt(t) - x, 0.0, 1.0));
    return f;
}

// No anti-aliasing: each pixel takes its centre's value.
FloatImage pointSampled(int t) {
    FloatImage f{kW, kH, 1, std::vector<float>(static_cast<size_t>(kW * kH))};
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) f.at(x, y, 0) = x + 0.5 < edgeAt(t) ? 1.0f : 0.0f;
    return f;
}

std::vector<FloatImage> sequence(FloatImage (*frame)(int, int), int channels = 1) {
    std::vector<FloatImage> s;
    for (int t = 0; t < kFrames; ++t) s.push_back(frame(t, channels));
    return s;
}

std::vector<FloatImage> pointSequence() {
    std::vector<FloatImage> s;
    for (int t = 0; t < kFrames; ++t) s.push_back(pointSampled(t));
    return s;
}

}  // namespace

// The closed form. The edge's phase in its pixel p, frac(edge), cycles
// 0.125 -> 0.375 -> 0.625 -> 0.875 -> 0.125 (of the next pixel); per row:
//   0.125 -> 0.375: truth: pixel p + 0.25; centres: none crosses (p + 0.5 is right
//                   of both positions): no change.        |d - r| summed: 0.25
//   0.375 -> 0.625: truth: pixel p + 0.25; centres: pixel p's centre p + 0.5 is
//                   crossed, it goes 0 -> 1.                |1 - 0.25| = 0.75
//   0.625 -> 0.875: truth: pixel p + 0.25; centres: none.   0.25
//   0.875 -> 1.125: truth: pixels p and p + 1 + 0.125 each (the edge crosses the
//                   pixel border); centres: none.           0.125 + 0.125 = 0.25
// Each pair's error is that sum over the row divided by the row's kW pixels
// (every row alike): 0.25 / kW, 0.75 / kW, 0.25 / kW, 0.25 / kW in turn, and
// over the 16 pairs (4 whole cycles) the mean is 1.5 / 4 / kW = 0.375 / kW =
// 0.0234375. The flicker is the 0.75 pair: the centres' image stands still for
// three frames and jumps a whole pixel on the fourth, where the truth moves
// a quarter each frame.
TEST(TemporalError, ASubPixelMovingEdgeWithoutAntialiasingHasTheClosedFormError) {
    const auto truth = sequence(&boxFiltered);
    const auto centres = pointSequence();
    const TemporalErrorResult r = TemporalError::measure(truth, centres);
    ASSERT_EQ(r.pairs.size(), static_cast<size_t>(kFrames - 1));
    const double expected[4] = {0.25 / kW, 0.75 / kW, 0.25 / kW, 0.25 / kW};
    for (size_t t = 0; t < r.pairs.size(); ++t) EXPECT_NEAR(r.pairs[t], expected[t % 4], 1e-12) << "pair " << t;
    EXPECT_NEAR(r.mean, 0.375 / kW, 1e-12);
    ASSERT_TRUE(r.interval.valid());
    EXPECT_LE(r.interval.low, r.mean);
    EXPECT_GE(r.interval.high, r.mean);
    EXPECT_GE(r.interval.low, 0.25 / kW - 1e-12);  // between the smallest and largest pair
    EXPECT_LE(r.interval.high, 0.75 / kW + 1e-12);
    EXPECT_LT(r.interval.low, r.interval.high);
}

// The truth against itself changes as the truth does: 0, with a zero-width
// interval; a constant offset (a bias in every frame) cancels too.
TEST(TemporalError, TheTruthAgainstItselfOrOffsetByAConstantIsZero) {
    const auto truth = sequence(&boxFiltered);
    const TemporalErrorResult same = TemporalError::measure(truth, truth);
    EXPECT_EQ(same.mean, 0.0);
    EXPECT_EQ(same.interval.low, 0.0);
    EXPECT_EQ(same.interval.high, 0.0);
    auto offset = truth;
    for (auto& f : offset)
        for (auto& v : f.pixels) v += 0.5f;  // exact in float: multiples of 1/8 plus 1/2
    EXPECT_EQ(TemporalError::measure(truth, offset).mean, 0.0);
}

// A test that stands still while the truth moves (lag, ghosting at its
// extreme) misses the whole change: each pair's error is the truth's
// change, 0.25 summed over a row, 0.25 / kW.
TEST(TemporalError, ATestThatLagsMissesTheTruthsChange) {
    const auto truth = sequence(&boxFiltered);
    const std::vector<FloatImage> frozen(kFrames, truth.front());
    const TemporalErrorResult r = TemporalError::measure(truth, frozen);
    for (double e : r.pairs) EXPECT_NEAR(e, 0.25 / kW, 1e-12);
}

// RGB frames are read as their luminance (Rec. 709 weights): grey frames
// give the one-channel answer.
TEST(TemporalError, RgbFramesAreReadAsTheirLuminance) {
    const auto grey = sequence(&boxFiltered, 3);
    std::vector<FloatImage> centres;
    for (const FloatImage& f : pointSequence()) {
        FloatImage rgb{f.width, f.height, 3, {}};
        for (float v : f.pixels) rgb.pixels.insert(rgb.pixels.end(), {v, v, v});
        centres.push_back(rgb);
    }
    EXPECT_NEAR(TemporalError::measure(grey, centres).mean, 0.375 / kW, 1e-9);
}

// Bad input: one line naming the frame.
TEST(TemporalError, RefusesSequencesOfOtherLengthsShapesOrNonFinitePixels) {
    const auto truth = sequence(&boxFiltered);
    auto shorter = truth;
    shorter.pop_back();
    auto expectThrow = [](const std::vector<FloatImage>& a, const std::vector<FloatImage>& b, const std::string& says) {
        try {
            TemporalError::measure(a, b);
            ADD_FAILURE() << "no error; expected '" << says << "'";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
        }
    };
    expectThrow(truth, shorter, "the reference has 17 frames, the test 16");
    expectThrow({truth[0]}, {truth[0]}, "needs at least 2 frames");
    auto resized = truth;
    resized[5] = boxFiltered(5, 3);
    expectThrow(truth, resized, "test frame 5 is 16x2x3, reference frame 0 is 16x2x1");
    auto bad = truth;
    bad[3].at(4, 1, 0) = std::nanf("");
    expectThrow(bad, truth, "reference frame 3: pixel (4, 1) channel 0 is NaN");
}

}  // namespace dw
