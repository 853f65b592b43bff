// The shadow-edge mask and the masked metrics (renderer/metrics/ShadowEdgeMask,
// MaskedMetrics) on synthetic shadow images whose edges are known by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/Error.h"
#include "renderer/io/ImageIO.h"
#include "renderer/metrics/Flip.h"
#include "renderer/metrics/MaskedMetrics.h"
#include "renderer/metrics/ShadowEdgeMask.h"

using namespace dw;

namespace {

FloatImage flatImage(int w, int h, int channels, float value) {
    FloatImage img;
    img.width = w;
    img.height = h;
    img.channels = channels;
    img.pixels.assign(static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(channels), value);
    return img;
}

// Shadowed (0) left of column `edge`, lit (1) from it on.
FloatImage halfShadow(int w, int h, int edge) {
    FloatImage s = flatImage(w, h, 1, 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < edge; ++x) s.at(x, y, 0) = 0.0f;
    return s;
}

}  // namespace

TEST(ShadowEdgeMask, StraightEdgeMarksTwoPixelsEachSideOfTheBoundaryPairPlusDilation) {
    const FloatImage mask = ShadowEdgeMask::fromShadow(halfShadow(40, 30, 20));
    ASSERT_EQ(mask.width, 40);
    ASSERT_EQ(mask.height, 30);
    ASSERT_EQ(mask.channels, 1);
    // Edge pixels: columns 19 and 20 (their 3x3 holds both values); dilated
    // by 2: columns 17..22, every row.
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) EXPECT_EQ(mask.at(x, y, 0), (x >= 17 && x <= 22) ? 1.0f : 0.0f) << x << "," << y;
    EXPECT_EQ(ShadowEdgeMask::count(mask), 6 * 30);
}

TEST(ShadowEdgeMask, OnePixelShadowGivesASevenBySevenSquareAndClampsAtTheBorder) {
    FloatImage s = flatImage(20, 20, 1, 1.0f);
    s.at(10, 10, 0) = 0.0f;
    EXPECT_EQ(ShadowEdgeMask::count(ShadowEdgeMask::fromShadow(s)), 7 * 7);  // 3x3 edges, +2 each way
    ShadowEdgeSettings none;
    none.dilation = 0;
    EXPECT_EQ(ShadowEdgeMask::count(ShadowEdgeMask::fromShadow(s, none)), 3 * 3);
    FloatImage corner = flatImage(20, 20, 1, 1.0f);
    corner.at(0, 0, 0) = 0.0f;
    EXPECT_EQ(ShadowEdgeMask::count(ShadowEdgeMask::fromShadow(corner)), 4 * 4);  // 2x2 edges, +2 inward
}

TEST(ShadowEdgeMask, SmoothVariationAndUniformImagesHaveNoEdgesButPartialShadowsDo) {
    FloatImage ramp = flatImage(50, 10, 1, 0.0f);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 50; ++x) ramp.at(x, y, 0) = 0.5f + 0.01f * static_cast<float>(x);  // 0.02 per 3x3
    EXPECT_EQ(ShadowEdgeMask::count(ShadowEdgeMask::fromShadow(ramp)), 0);
    EXPECT_EQ(ShadowEdgeMask::count(ShadowEdgeMask::fromShadow(flatImage(8, 8, 1, 0.0f))), 0);
    // One of two equal lights shadowed: 1 -> 0.5 is an edge.
    FloatImage half = halfShadow(40, 30, 20);
    for (float& v : half.pixels) v = 0.5f + 0.5f * v;
    EXPECT_EQ(ShadowEdgeMask::count(ShadowEdgeMask::fromShadow(half)), 6 * 30);
}

TEST(ShadowEdgeMask, RefusesAColourImage) {
    EXPECT_THROW(ShadowEdgeMask::fromShadow(flatImage(8, 8, 3, 1.0f)), Error);
}

TEST(MaskedMetrics, RmsMeanAndPsnrCountOnlyMaskedPixels) {
    const FloatImage mask = ShadowEdgeMask::fromShadow(halfShadow(40, 30, 20));  // 180 pixels
    const FloatImage ref = flatImage(40, 30, 3, 0.25f);
    FloatImage test = ref;
    test.at(18, 5, 1) += 0.5f;  // inside the mask: one channel
    test.at(2, 5, 0) += 1.0f;   // outside: ignored
    const double n = 180.0 * 3.0;
    EXPECT_NEAR(MaskedMetrics::rms(ref, test, mask), std::sqrt(0.25 / n), 1e-9);
    EXPECT_NEAR(MaskedMetrics::meanAbs(ref, test, mask), 0.5 / n, 1e-9);
    EXPECT_NEAR(MaskedMetrics::psnr(ref, test, mask), 20.0 * std::log10(1.0 / std::sqrt(0.25 / n)), 1e-6);
    EXPECT_EQ(MaskedMetrics::psnr(ref, ref, mask), std::numeric_limits<double>::infinity());
    // The whole-image mask gives the unmasked figure.
    const FloatImage all = flatImage(40, 30, 1, 1.0f);
    EXPECT_NEAR(MaskedMetrics::rms(ref, test, all), std::sqrt((0.25 + 1.0) / (40.0 * 30.0 * 3.0)), 1e-9);
}

TEST(MaskedMetrics, FlipMapMeanOverTheMaskOnly) {
    const FloatImage mask = ShadowEdgeMask::fromShadow(halfShadow(40, 30, 20));
    FloatImage map = flatImage(40, 30, 1, 0.0f);
    for (int y = 0; y < 30; ++y) {
        map.at(17, y, 0) = 0.6f;  // inside
        map.at(0, y, 0) = 1.0f;   // outside
    }
    EXPECT_NEAR(MaskedMetrics::mapMean(map, mask), 0.6 * 30 / 180.0, 1e-7);
    // On a real FLIP map: an error only outside the mask reads 0 inside it.
    FloatImage ref = flatImage(40, 30, 3, 0.5f), test = ref;
    for (int y = 0; y < 30; ++y)
        for (int c = 0; c < 3; ++c) test.at(0, y, c) = 0.0f;
    const FlipResult flip = Flip::ldr(ref, test);
    EXPECT_GT(flip.mean, 0.0);
    EXPECT_LT(MaskedMetrics::mapMean(flip.map, mask), 1e-6);
}

TEST(MaskedMetrics, EmptyMaskAndShapeMismatchAreRefusedWithAMessage) {
    const FloatImage ref = flatImage(8, 8, 3, 0.5f);
    try {
        MaskedMetrics::rms(ref, ref, flatImage(8, 8, 1, 0.0f));
        FAIL() << "no throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no pixel"), std::string::npos) << e.what();
    }
    EXPECT_THROW(MaskedMetrics::rms(ref, ref, flatImage(4, 8, 1, 1.0f)), Error);
    EXPECT_THROW(MaskedMetrics::rms(ref, flatImage(8, 8, 4, 0.5f), flatImage(8, 8, 1, 1.0f)), Error);
    EXPECT_THROW(MaskedMetrics::mapMean(flatImage(8, 8, 1, 0.0f), flatImage(8, 8, 1, 0.0f)), Error);
}
