// The parts of `tradeoff` and `bench --exclude` that need no GL: the sweep's
// points, the excluded corners, the error with its interval, the bootstrap
// of a median.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/Error.h"
#include "renderer/RunConfig.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/bench/ConfigurationRunner.h"
#include "renderer/bench/GridExclusion.h"
#include "renderer/bench/ImageError.h"
#include "renderer/bench/TradeoffSweep.h"

using namespace dw;

namespace {

TradeoffSweep grid() {
    TradeoffSweep s;
    s.axes = {{"ssao.samples", {"8", "16", "32"}}, {"ssao.resolution", {"full", "half"}}};
    return s;
}

std::vector<int> indices(const std::vector<TradeoffPoint>& points) {
    std::vector<int> out;
    for (const auto& p : points) out.push_back(p.index);
    return out;
}

FloatImage grey(int w, int h, float v) {
    FloatImage i;
    i.width = w;
    i.height = h;
    i.channels = 1;
    i.pixels.assign(static_cast<size_t>(w) * h, v);
    return i;
}

}  // namespace

TEST(TradeoffSweep, GridOrderOneAtATimeAndExclusion) {
    TradeoffSweep s = grid();
    const auto points = s.points();
    ASSERT_EQ(points.size(), 6u);
    EXPECT_EQ(points[1].values, (std::vector<std::string>{"8", "half"}));
    EXPECT_EQ(points[2].values, (std::vector<std::string>{"16", "full"}));

    // A corner, and a slice (an item without '=' adds a value to the axis before it).
    s.exclusion.add("ssao.samples=32,ssao.resolution=half");
    s.exclusion.add("ssao.samples=8,16");
    s.exclusion.resolve({{"ssao.samples", {"8", "16", "32"}}, {"ssao.resolution", {"full", "half"}}});
    EXPECT_EQ(indices(s.points()), (std::vector<int>{4}));  // exactly those left out; numbers kept
    EXPECT_EQ(s.count(), 6u);

    TradeoffSweep all = grid();
    all.exclusion.add("ssao.resolution=full,half");
    try {
        all.points();
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "the sweep is empty after --exclude: every one of its 6 point(s) is left out");
    }
    GridExclusion bad;
    bad.add("ssao.radius=1");
    EXPECT_THROW(bad.resolve({{"ssao.samples", {"8"}}}), Error);
    GridExclusion value;
    value.add("ssao.samples=9");
    try {
        value.resolve({{"ssao.samples", {"8", "16"}}});
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "--exclude ssao.samples=9: ssao.samples is never '9' in this sweep (8, 16)");
    }
    EXPECT_THROW(GridExclusion().add("8,16"), Error);
    EXPECT_THROW(GridExclusion().add("a=1,a=2"), Error);

    TradeoffSweep one;
    one.oneAtATime = true;
    one.axes = {{"a", {"1", "2", "3"}}, {"b", {"x", "y"}}};
    one.centre = {"2", "x"};
    const auto p = one.points();
    ASSERT_EQ(p.size(), 4u);
    EXPECT_EQ(p[0].values, (std::vector<std::string>{"2", "x"}));
    EXPECT_EQ(p[1].values, (std::vector<std::string>{"1", "x"}));
    EXPECT_EQ(p[2].values, (std::vector<std::string>{"3", "x"}));
    EXPECT_EQ(p[3].values, (std::vector<std::string>{"2", "y"}));
    EXPECT_EQ(one.count(), 4u);
}

TEST(TradeoffSweep, AroundCurrentTakesEveryTradeoffKnob) {
    const KnobRegistry knobs = RunConfig::declaredKnobs();
    const TradeoffSweep s = TradeoffSweep::aroundCurrent(knobs);
    ASSERT_FALSE(s.axes.empty());
    EXPECT_TRUE(s.oneAtATime);
    for (size_t a = 0; a < s.axes.size(); ++a) {
        const int id = *knobs.find(s.axes[a].name);
        EXPECT_TRUE(knobs.spec(id).tradeoff) << s.axes[a].name;
        EXPECT_EQ(s.centre[a], knobs.format(id));
        EXPECT_GE(s.axes[a].values.size(), 2u);
    }
    // ssao.samples (16 by default): 4, 8, 16, 32, 64.
    for (size_t a = 0; a < s.axes.size(); ++a)
        if (s.axes[a].name == "ssao.samples") {
            EXPECT_EQ(s.axes[a].values, (std::vector<std::string>{"4", "8", "16", "32", "64"}));
        }
}

TEST(ImageError, MetricsAndTheirIntervals) {
    FloatImage a = grey(64, 48, 0.5f), b = grey(64, 48, 0.5f);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) b.at(x, y, 0) = 0.5f + ((x + y) % 2 ? 0.1f : -0.1f) * (x < 32 ? 1.0f : 2.0f);
    const ErrorEstimate rms = ImageError::measure(a, b, "rms", true, 500);
    // Half the pixels differ by 0.1, half by 0.2: sqrt((0.01 + 0.04) / 2).
    EXPECT_NEAR(rms.value, std::sqrt(0.025), 1e-6);
    EXPECT_LT(rms.low, rms.value);
    EXPECT_GT(rms.high, rms.value);
    EXPECT_GT(rms.low, 0.1);
    EXPECT_LT(rms.high, 0.2);
    const ErrorEstimate same = ImageError::measure(a, a, "rms", true, 200);
    EXPECT_EQ(same.value, 0.0);
    EXPECT_EQ(same.high, 0.0);
    const ErrorEstimate psnr = ImageError::measure(a, b, "psnr", true, 200);
    EXPECT_LE(psnr.low, psnr.value);
    EXPECT_GE(psnr.high, psnr.value);
    const ErrorEstimate flip = ImageError::measure(a, b, "flip", true, 200);
    EXPECT_GT(flip.value, 0.0);
    EXPECT_LE(flip.low, flip.value + 1e-12);
    EXPECT_THROW(ImageError::measure(a, b, "mse", true), Error);
    EXPECT_THROW(ImageError::measure(a, grey(8, 8, 0.0f), "rms", true), Error);

    const ErrorEstimate mean = ImageError::meanOver({1.0, 2.0, 3.0}, 500);
    EXPECT_DOUBLE_EQ(mean.value, 2.0);
    EXPECT_GE(mean.low, 1.0);
    EXPECT_LE(mean.high, 3.0);
    // A camera without an error is left out of the mean (issue 23), not the whole mean lost.
    EXPECT_DOUBLE_EQ(ImageError::meanOver({1.0, NAN}).value, 1.0);
    EXPECT_TRUE(std::isnan(ImageError::meanOver({NAN, NAN}).value));

    const MedianInterval m = bootstrapMedian({1.0, 2.0, 3.0, 4.0, 100.0}, 500);
    EXPECT_TRUE(m.valid());
    EXPECT_GE(m.low, 1.0);
    EXPECT_LE(m.high, 100.0);
    EXPECT_FALSE(bootstrapMedian({}).valid());
}

// bench's time left (issue 23: "about 2:45 left" for a run that took 11:37):
// each configuration's rounds at its own measured round time (warm-up and
// block included), not the run's mean time per counted frame; the ones not
// timed yet at the mean of those timed (the progress line says how many).
TEST(ConfigurationRunner, TimeLeftFromEachConfigurationsRoundTime) {
    // Three configurations, 10 rounds each; two fast ones (1 s a round) timed once,
    // the slow third (10 s a round) not reached yet: it counts at their mean.
    EXPECT_DOUBLE_EQ(ConfigurationRunner::timeLeft({1.0, 1.0, -1.0}, {9, 9, 10}), 9 + 9 + 10 * 1.0);
    // Once the slow one is timed, its rounds count at its own time: 9 + 9 + 90.
    EXPECT_DOUBLE_EQ(ConfigurationRunner::timeLeft({1.0, 1.0, 10.0}, {9, 9, 9}), 108.0);
    // Resumed or excluded frames: a configuration with no rounds left adds nothing,
    // however slow (a mean per frame over the run would still weigh it).
    EXPECT_DOUBLE_EQ(ConfigurationRunner::timeLeft({10.0, 1.0}, {0, 9}), 9.0);
    EXPECT_DOUBLE_EQ(ConfigurationRunner::timeLeft({-1.0, -1.0}, {3, 3}), 0.0);
    EXPECT_DOUBLE_EQ(ConfigurationRunner::timeLeft({2.0, 4.0}, {0, 0}), 0.0);
}
