#include <gtest/gtest.h>

#include "renderer/graph/ChangeCost.h"
#include "renderer/graph/PassTimer.h"

#include <stdexcept>

using namespace dw;

TEST(TimingStats, MedianMeanMinMax) {
    const TimingStats odd = computeStats({5.0f, 1.0f, 3.0f});
    EXPECT_FLOAT_EQ(odd.median, 3.0f);
    EXPECT_FLOAT_EQ(odd.mean, 3.0f);
    EXPECT_FLOAT_EQ(odd.min, 1.0f);
    EXPECT_FLOAT_EQ(odd.max, 5.0f);
    const TimingStats even = computeStats({4.0f, 1.0f, 2.0f, 100.0f});
    EXPECT_FLOAT_EQ(even.median, 3.0f);  // robust to the outlier
    EXPECT_EQ(even.count, 4);
    EXPECT_EQ(computeStats({}).count, 0);
}

// The cost of a change from synthetic histories: 40 frames of ssao at about
// 70 ms, a change, 3 frames to settle, 40 frames at about 114 ms.
TEST(ChangeCost, ReportsTheMediansTheDifferenceAndASignificantRatio) {
    PassTimer timer;
    auto jitter = [](int i) { return static_cast<float>((i * 37) % 11 - 5) * 0.4f; };
    for (int f = 0; f < 40; ++f) {
        timer.addSample("ssao", {static_cast<std::uint64_t>(f), 70.0f + jitter(f), 1.0f});
        timer.addSample("tonemap", {static_cast<std::uint64_t>(f), 2.0f + jitter(f) * 0.01f, 0.1f});
        timer.addSample(PassTimer::kFrameSeries, {static_cast<std::uint64_t>(f), 90.0f + jitter(f), 2.0f});
    }
    ChangeCost cost;
    cost.mark(timer, 39, "ssao.samples 16 -> 64", 120, 3);
    // Frames 40-42 re-create resources: slow, and left out.
    for (int f = 40; f < 83; ++f) {
        const float ssao = f < 43 ? 900.0f : 114.0f + jitter(f);
        timer.addSample("ssao", {static_cast<std::uint64_t>(f), ssao, 1.0f});
        timer.addSample("tonemap", {static_cast<std::uint64_t>(f), 2.0f + jitter(f + 3) * 0.01f, 0.1f});
        timer.addSample(PassTimer::kFrameSeries, {static_cast<std::uint64_t>(f), ssao + 20.0f, 2.0f});
        if (f == 60) timer.addSample("bloom", {static_cast<std::uint64_t>(f), 5.0f, 0.1f});
    }
    EXPECT_EQ(cost.afterFrames(timer), 40);
    const auto costs = cost.costs(timer);
    auto find = [&](const std::string& n) -> const PassChangeCost& {
        for (const auto& c : costs)
            if (c.pass == n) return c;
        throw std::runtime_error("no " + n);
    };
    const PassChangeCost& ssao = find("ssao");
    EXPECT_EQ(ssao.beforeFrames, 40);
    EXPECT_EQ(ssao.afterFrames, 40);
    EXPECT_NEAR(ssao.beforeMs, 70.0, 2.1);
    EXPECT_NEAR(ssao.afterMs, 114.0, 2.1);
    EXPECT_TRUE(ssao.significant());
    EXPECT_NEAR(ssao.ratio.ratio, 114.0 / 70.0, 0.05);
    EXPECT_LT(ssao.ratio.low, ssao.ratio.ratio);
    EXPECT_GT(ssao.ratio.high, ssao.ratio.ratio);
    EXPECT_GT(ssao.ratio.low, 1.5);
    EXPECT_EQ(ssao.describe().substr(0, 7), "+44.0 m") << ssao.describe();
    EXPECT_NE(ssao.describe().find("95% CI"), std::string::npos);
    // Unchanged within its noise: not significant.
    EXPECT_FALSE(find("tonemap").significant()) << find("tonemap").describe();
    // A pass that runs only since the change.
    EXPECT_EQ(find("bloom").beforeFrames, 0);
    EXPECT_EQ(find("bloom").describe(), "new: 5.000 ms");
}
