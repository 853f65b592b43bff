// FiniteCheck (issue 10, part 9): counts NaN, +Inf and -Inf per produced
// buffer in pipeline order and finds the first pixel, so `render
// --check-finite` can name the buffer where a non-finite value entered.
#include <gtest/gtest.h>

#include <limits>

#include "renderer/gl/Texture.h"
#include "renderer/inspect/BufferView.h"
#include "renderer/inspect/FiniteCheck.h"
#include "renderer/inspect/OutputReadback.h"
#include "tests/support/TestSupport.h"

using namespace dw;

TEST(FiniteCheck, CountsEachKindAndFindsTheFirstPixel) {
    FloatImage img{5, 3, 2, std::vector<float>(30, 1.0f)};
    img.at(3, 1, 1) = std::numeric_limits<float>::quiet_NaN();
    img.at(4, 1, 0) = std::numeric_limits<float>::infinity();
    img.at(0, 2, 0) = -std::numeric_limits<float>::infinity();
    const NonFiniteCount c = FiniteCheck::count(img, "x");
    EXPECT_EQ(c.values, 30);
    EXPECT_EQ(c.nan, 1);
    EXPECT_EQ(c.positiveInf, 1);
    EXPECT_EQ(c.negativeInf, 1);
    EXPECT_EQ(c.nonFinite(), 3);
    EXPECT_EQ(c.firstX, 3);
    EXPECT_EQ(c.firstY, 1);
}

TEST(FiniteCheck, ScansProducedBuffersInPipelineOrder) {
    auto session = test::makeSession(32, 32);  // a GL context
    OutputRegistry outputs;
    outputs.declare("first", {"clean", OutputKind::HdrColor, "finite values"});
    outputs.declare("second", {"dirty", OutputKind::HdrColor, "one NaN"});
    std::vector<float> values(4 * 4 * 4, 0.5f);
    gl::Texture clean = gl::Texture::create2D(GL_RGBA32F, 4, 4);
    clean.upload(0, 4, 4, GL_RGBA, GL_FLOAT, values.data());
    values[(2 * 4 + 1) * 4 + 2] = std::numeric_limits<float>::quiet_NaN();
    gl::Texture dirty = gl::Texture::create2D(GL_RGBA32F, 4, 4);
    dirty.upload(0, 4, 4, GL_RGBA, GL_FLOAT, values.data());
    outputs.bind("clean", &clean, 4);
    outputs.bind("dirty", &dirty, 4);
    outputs.markFrameStart();
    outputs.markProduced("first");
    outputs.markProduced("second");
    const std::vector<NonFiniteCount> counts = FiniteCheck::scan(outputs);
    ASSERT_EQ(counts.size(), 2u);
    EXPECT_EQ(counts[0].buffer, "clean");
    EXPECT_EQ(counts[0].nonFinite(), 0);
    EXPECT_EQ(counts[1].buffer, "dirty");
    EXPECT_EQ(counts[1].nan, 1);
    EXPECT_EQ(counts[1].firstX, 1);
    // Image rows read back top-down: GL row 2 of 4 is image row 1.
    EXPECT_EQ(counts[1].firstY, 1);
}

// The buffer viewer's non-finite view: NaN magenta, +Inf red, -Inf blue, the
// finite rest dim grey.
TEST(FiniteCheck, TheNonFiniteViewHighlightsEachKind) {
    auto session = test::makeSession(32, 32);
    std::vector<float> values(4 * 2 * 4, 0.5f);
    values[0 * 4 + 0] = std::numeric_limits<float>::quiet_NaN();      // GL row 0, column 0
    values[1 * 4 + 1] = std::numeric_limits<float>::infinity();       // column 1
    values[2 * 4 + 2] = -std::numeric_limits<float>::infinity();      // column 2
    gl::Texture tex = gl::Texture::create2D(GL_RGBA32F, 4, 2);
    tex.upload(0, 4, 2, GL_RGBA, GL_FLOAT, values.data());
    PublishedOutput o;
    o.decl = {"test.values", OutputKind::HdrColor, "values with NaN and infinities"};
    o.texture = &tex;
    o.channels = 4;
    o.producedThisFrame = true;
    BufferViewSettings s;
    s.mapping = BufferViewSettings::Mapping::NonFinite;
    const FloatImage img = readRgba8(session->bufferView().render(o, s));
    ASSERT_EQ(img.width, 4);
    const int row = img.height - 1;  // GL row 0 is the image's bottom row
    EXPECT_NEAR(img.at(0, row, 0), 1.0f, 0.01f);  // NaN: magenta
    EXPECT_NEAR(img.at(0, row, 1), 0.0f, 0.01f);
    EXPECT_NEAR(img.at(0, row, 2), 1.0f, 0.01f);
    EXPECT_NEAR(img.at(1, row, 0), 1.0f, 0.01f);  // +Inf: red
    EXPECT_NEAR(img.at(1, row, 2), 0.0f, 0.01f);
    EXPECT_NEAR(img.at(2, row, 0), 0.0f, 0.01f);  // -Inf: blue
    EXPECT_NEAR(img.at(2, row, 2), 1.0f, 0.01f);
    EXPECT_LT(img.at(3, row, 0), 0.3f);           // finite: dim grey
    EXPECT_NEAR(img.at(3, row, 0), img.at(3, row, 1), 0.01f);
    EXPECT_EQ(FiniteCheck::count(readOutputRaw(o), o.decl.name).nonFinite(), 3);
}
