// The timed rounds a step at a time (renderer/bench/ConfigurationRunner):
// begin/step/finish, the stepping a window drives between UI frames, renders
// the same blocks in the same order as measure() and hands back the same
// samples; skipped frames are neither rendered nor counted.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "renderer/Error.h"
#include "renderer/bench/ConfigurationRunner.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

struct Rendered {
    int config, sample;
    bool operator==(const Rendered& o) const { return config == o.config && sample == o.sample; }
};

// Two configurations (ssao.samples 8 and 16) of one session; every pose recorded.
struct TwoConfigurations {
    std::unique_ptr<RenderSession> session = test::makeSession(32, 18);
    std::vector<Rendered> poses;
    ConfigurationRunner runner;
    explicit TwoConfigurations(RunnerPlan plan)
        : runner(
              plan,
              [this](int c) -> RenderSession& {
                  session->knobs().applyAssignment(std::string("ssao.samples=") + (c == 0 ? "8" : "16"));
                  return *session;
              },
              [this](RenderSession&, int c, int k) { poses.push_back({c, k}); }) {
        session->loadScene("spheres");
    }
};

std::vector<std::tuple<int, int, std::string>> keys(const RunnerTimings& t) {
    std::vector<std::tuple<int, int, std::string>> k;
    for (const auto& s : t.samples) k.emplace_back(s.config, s.sample, s.series);
    return k;
}

}  // namespace

TEST(ConfigurationRunner, SteppingRendersWhatMeasureRendersAndGivesTheSameSamples) {
    RunnerPlan plan;
    plan.configurations = 2;
    plan.frames = 4;
    plan.warmup = 1;
    plan.block = 2;
    TwoConfigurations measured(plan), stepped(plan);
    const RunnerTimings a = measured.runner.measure("test", {});

    stepped.runner.begin("test", {});
    EXPECT_EQ(stepped.runner.fractionDone(), 0.0);
    int steps = 0;
    std::vector<double> done;
    while (stepped.runner.step()) {
        ASSERT_LT(++steps, 10);
        done.push_back(stepped.runner.fractionDone());
    }
    const RunnerTimings b = stepped.runner.finish();
    // Two rounds of two configurations: four blocks, the last ending the loop.
    EXPECT_EQ(steps, 3);
    EXPECT_EQ(done, (std::vector<double>{0.25, 0.5, 0.75}));
    // Warm-up (the block's first pose) then the block: c0 0 0 1, c1 0 0 1, c0 2 2 3, c1 2 2 3.
    const std::vector<Rendered> order = {{0, 0}, {0, 0}, {0, 1}, {1, 0}, {1, 0}, {1, 1},
                                         {0, 2}, {0, 2}, {0, 3}, {1, 2}, {1, 2}, {1, 3}};
    EXPECT_EQ(measured.poses, order);
    EXPECT_EQ(stepped.poses, order);
    EXPECT_EQ(keys(a), keys(b));
    int frames = 0;
    for (const auto& s : b.samples) frames += s.series == PassTimer::kFrameSeries;
    EXPECT_EQ(frames, 8);
    EXPECT_THROW(stepped.runner.step(), Error);  // finish() ended the measurement
}

TEST(ConfigurationRunner, SkippedFramesAreNeitherRenderedNorCounted) {
    RunnerPlan plan;
    plan.configurations = 2;
    plan.frames = 2;
    plan.warmup = 0;
    plan.block = 1;
    TwoConfigurations run(plan);
    // Configuration 0's frames are already measured (a resumed run): only configuration 1's render.
    const RunnerTimings t = run.runner.measure("test", {}, {}, {}, [](int c, int) { return c == 0; });
    EXPECT_EQ(run.poses, (std::vector<Rendered>{{1, 0}, {1, 1}}));
    for (const auto& s : t.samples) EXPECT_EQ(s.config, 1) << s.series;
}
