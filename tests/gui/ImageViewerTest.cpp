// The texture viewer's arithmetic (placement, zoom at the cursor, pan), its
// per-output settings, and the histogram of an image (OpenImageIO).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/io/ImageHistogram.h"
#include "ui/UiState.h"

using namespace dw;
using namespace dw::ui;

TEST(ImageViewer, FitsTheImageAndZoomsAtTheCursorKeepingThePointUnderIt) {
    ImageView view;
    // A 200x100 image in a 400x400 box: fit by width, centred vertically.
    ImagePlacement p = placeImage({200, 100}, {10, 20}, {400, 400}, view);
    EXPECT_FLOAT_EQ(p.fitScale, 2.0f);
    EXPECT_FLOAT_EQ(p.size.x, 400.0f);
    EXPECT_FLOAT_EQ(p.size.y, 200.0f);
    EXPECT_FLOAT_EQ(p.min.x, 10.0f);
    EXPECT_FLOAT_EQ(p.min.y, 120.0f);
    // Zoom 4x at a point: the image point under it stays under it.
    const glm::vec2 cursor(110.0f, 170.0f);
    const glm::vec2 before = p.uvAt(cursor);
    zoomAt(view, 4.0f, cursor, p);
    const ImagePlacement q = placeImage({200, 100}, {10, 20}, {400, 400}, view);
    EXPECT_FLOAT_EQ(view.zoom, 4.0f);
    EXPECT_NEAR(q.uvAt(cursor).x, before.x, 1e-5f);
    EXPECT_NEAR(q.uvAt(cursor).y, before.y, 1e-5f);
    EXPECT_FLOAT_EQ(q.size.x, 1600.0f);
    // 1:1 is zoom 1 / fitScale: one image pixel per screen pixel.
    view.zoom = 1.0f / p.fitScale;
    EXPECT_FLOAT_EQ(placeImage({200, 100}, {10, 20}, {400, 400}, view).size.x, 200.0f);
}

TEST(ImageViewer, DisplaySettingsAreKeptPerOutput) {
    ViewportView v;
    v.output = "lbuffer";
    v.settings().channel = BufferViewSettings::Channel::R;
    v.settings().mapping = BufferViewSettings::Mapping::Heatmap;
    v.output = "ao.filtered";
    EXPECT_EQ(v.settingsOr().channel, BufferViewSettings::Channel::RGB);
    EXPECT_EQ(v.settingsOr().mapping, BufferViewSettings::Mapping::Auto);
    v.output = "lbuffer";
    EXPECT_EQ(v.settingsOr().channel, BufferViewSettings::Channel::R);
}

TEST(ImageViewer, ZoomPanAndHistogramAreKeptPerOutputToo) {
    ViewportView v;
    v.show("lbuffer");
    v.zoom = 16.0f;
    v.center = {0.25f, 0.75f};
    v.histogram = true;
    v.show("ao.filtered");
    // Another buffer starts fitted, without the lbuffer's histogram.
    EXPECT_FLOAT_EQ(v.zoom, 1.0f);
    EXPECT_EQ(v.center, glm::vec2(0.5f));
    EXPECT_FALSE(v.histogram);
    v.zoom = 2.0f;
    v.show("lbuffer");
    EXPECT_FLOAT_EQ(v.zoom, 16.0f);
    EXPECT_EQ(v.center, glm::vec2(0.25f, 0.75f));
    EXPECT_TRUE(v.histogram);
    v.show("ao.filtered");
    EXPECT_FLOAT_EQ(v.zoom, 2.0f);
}

TEST(ImageViewer, OnACpuRasteriserTheWindowStartsAtAutoFromAQuarterUnlessTold) {
    const StartResolution cpu = startResolution("", true, false);
    EXPECT_EQ(cpu.scale, ResolutionScale::Auto);
    EXPECT_FLOAT_EQ(cpu.autoScale, 0.25f);
    EXPECT_FLOAT_EQ(cpu.frameTargetMs, 150.0f);
    EXPECT_TRUE(cpu.softwareDefault);
    // A GPU, a scripted run or an explicit --resolution: as asked, full by default.
    EXPECT_EQ(startResolution("", false, false).scale, ResolutionScale::Full);
    EXPECT_EQ(startResolution("", true, true).scale, ResolutionScale::Full);
    EXPECT_EQ(startResolution("full", true, false).scale, ResolutionScale::Full);
    EXPECT_FALSE(startResolution("full", true, false).softwareDefault);
    EXPECT_EQ(startResolution("1/2", true, false).scale, ResolutionScale::Half);
    EXPECT_EQ(startResolution("auto", false, false).scale, ResolutionScale::Auto);
    EXPECT_FLOAT_EQ(startResolution("auto", false, false).autoScale, 1.0f);
}

TEST(ImageViewer, HistogramCountsFiniteValuesPerChannelAndCountsNanAndInfApart) {
    FloatImage img;
    img.width = 10;
    img.height = 10;
    img.channels = 2;
    img.pixels.resize(200);
    for (int i = 0; i < 100; ++i) {
        img.pixels[2 * i] = static_cast<float>(i % 10);  // 0..9, ten of each
        img.pixels[2 * i + 1] = 4.5f;                    // constant
    }
    img.pixels[2 * 7] = std::numeric_limits<float>::quiet_NaN();
    img.pixels[2 * 8] = std::numeric_limits<float>::infinity();
    const ImageHistogram h = computeHistogram(img, 10);
    ASSERT_EQ(h.channels.size(), 2u);
    EXPECT_FLOAT_EQ(h.lo, 0.0f);
    EXPECT_NEAR(h.hi, 9.0f, 1e-5f);
    EXPECT_EQ(h.channels[0].nan, 1u);
    EXPECT_EQ(h.channels[0].inf, 1u);
    std::uint64_t total = 0;
    for (auto c : h.channels[0].counts) total += c;
    EXPECT_EQ(total, 98u);  // the NaN and the Inf are not in any bin
    EXPECT_EQ(h.channels[0].counts[0], 10u);
    EXPECT_EQ(h.channels[0].counts[7], 9u);  // one 7 was the NaN
    std::uint64_t second = 0;
    for (auto c : h.channels[1].counts) second += c;
    EXPECT_EQ(second, 100u);
    EXPECT_EQ(h.channels[1].counts[4] + h.channels[1].counts[5], 100u);
}
