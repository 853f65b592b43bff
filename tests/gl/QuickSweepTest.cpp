// The workbench's quick sweep of one knob (renderer/bench/QuickSweep): every
// value rendered and timed in turns, measured with FLIP against a baseline,
// the table's front marked, the session's knob untouched.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/bench/QuickSweep.h"
#include "tests/support/TestSupport.h"

using namespace dw;

TEST(QuickSweep, ValuesOfEachKindOfKnob) {
    const KnobRegistry knobs = RunConfig::declaredKnobs();
    EXPECT_EQ(QuickSweep::valuesOf(knobs, "gbuffer.normal_encoding"), (std::vector<std::string>{"kl16", "oct16", "oct8"}));
    EXPECT_EQ(QuickSweep::valuesOf(knobs, "ao.enabled"), (std::vector<std::string>{"false", "true"}));
    const auto samples = QuickSweep::valuesOf(knobs, "ssao.samples");
    const KnobSpec& s = knobs.spec(*knobs.find("ssao.samples"));
    ASSERT_EQ(samples.size(), 5u);
    EXPECT_EQ(samples.front(), std::to_string(static_cast<int>(s.minValue)));
    EXPECT_EQ(samples.back(), std::to_string(static_cast<int>(s.maxValue)));
    EXPECT_THROW(QuickSweep::valuesOf(knobs, "ssao.sample"), Error);
}

TEST(QuickSweep, NormalEncodingsAgainstTheCurrentImage) {
    auto session = test::makeSession(128, 72);
    session->loadScene("spheres");
    session->render({{"final"}});
    const FloatImage current = session->readRaw("final");
    QuickSweep sweep;
    sweep.start(session->knobs(), "gbuffer.normal_encoding", current, "the current image", 3);
    int steps = 0;
    while (sweep.step(*session)) ASSERT_LT(++steps, 20);
    ASSERT_TRUE(sweep.done()) << sweep.error();
    EXPECT_EQ(session->knobs().format(*session->knobs().find("gbuffer.normal_encoding")), "kl16");
    const TradeoffTable& t = sweep.table();
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_EQ(t.axes, (std::vector<std::string>{"gbuffer.normal_encoding"}));
    for (const TradeoffRow& r : t.rows) {
        EXPECT_EQ(r.metric, "flip");
        EXPECT_EQ(r.frames, 3) << r.axisValues[0];
        EXPECT_TRUE(std::isfinite(r.frameGpuMs) && r.frameGpuMs > 0.0) << r.axisValues[0];
        EXPECT_LE(r.frameGpuMsLo, r.frameGpuMs);
        EXPECT_GE(r.frameGpuMsHi, r.frameGpuMs);
    }
    // kl16 is the current setting: the same image. oct16 differs by a few
    // normals' rounding, oct8 by about a degree everywhere.
    std::printf("quick sweep FLIP: kl16 %.6f, oct16 %.6f, oct8 %.6f\n", t.rows[0].error, t.rows[1].error, t.rows[2].error);
    EXPECT_EQ(t.rows[0].error, 0.0);
    EXPECT_LT(t.rows[1].error, t.rows[2].error);
    EXPECT_GT(t.rows[2].error, 0.0);
    EXPECT_TRUE(t.rows[0].pareto);  // no error: nothing beats it on both
}
