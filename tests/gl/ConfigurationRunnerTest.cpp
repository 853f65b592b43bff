// The timed rounds a step at a time (renderer/bench/ConfigurationRunner):
// begin/step/finish, the stepping a window drives between UI frames, renders
// the same blocks in the same order as measure() and hands back the same
// samples; skipped frames are neither rendered nor counted.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "renderer/Error.h"
#include "renderer/bench/ChangeMeasurement.h"
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
        ASSERT_LT(++steps, 20);
        done.push_back(stepped.runner.fractionDone());
    }
    const RunnerTimings b = stepped.runner.finish();
    // A frame a step: two rounds of two configurations, four blocks of a
    // warm-up and two counted frames; the last frame's step ends the loop.
    EXPECT_EQ(steps, 11);
    EXPECT_EQ(done, (std::vector<double>{0, 0.125, 0.25, 0.25, 0.375, 0.5, 0.5, 0.625, 0.75, 0.75, 0.875}));
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

// A window's loop puts its own state back between steps (the quick sweep, a
// record): with selectEveryFrame the configuration is made current before
// every frame, so each frame renders it; plan.request is what each frame asks
// for (a record of another buffer).
TEST(ConfigurationRunner, SelectEveryFrameRendersTheConfigurationWhateverTheCallerDidBetweenSteps) {
    RunnerPlan plan;
    plan.configurations = 2;
    plan.frames = 2;
    plan.warmup = 1;
    plan.block = 2;
    plan.selectEveryFrame = true;
    plan.request = FrameRequest{{"ao.raw"}};
    TwoConfigurations run(plan);
    const int samples = *run.session->knobs().find("ssao.samples");
    std::vector<double> seen;
    ConfigurationRunner runner(
        plan,
        [&](int c) -> RenderSession& {
            run.session->knobs().applyAssignment(std::string("ssao.samples=") + (c == 0 ? "8" : "16"));
            return *run.session;
        },
        [&](RenderSession& s, int, int) { seen.push_back(s.knobs().value(samples)); });
    runner.begin("test", {});
    do {
        run.session->knobs().applyAssignment("ssao.samples=32");  // the window's own state between steps
    } while (runner.step());
    const RunnerTimings t = runner.finish();
    EXPECT_EQ(seen, (std::vector<double>{8, 8, 8, 16, 16, 16}));
    int frames = 0, tonemap = 0;
    for (const auto& s : t.samples) {
        frames += s.series == PassTimer::kFrameSeries;
        tonemap += s.series == "tonemap";
    }
    EXPECT_EQ(frames, 4);
    EXPECT_EQ(tonemap, 0) << "asked for ao.raw alone, the frame culls the passes after it";
    EXPECT_TRUE(std::any_of(t.samples.begin(), t.samples.end(), [](const BenchSample& s) { return s.series == "ao"; }));
}

// The cost of a change on the runner: before (0) and after (1) in turns of
// perTurn counted frames, settle frames left out after each switch, a frame a
// step; the view's own state (the after values) is put back after every
// step; the verdict has each side's frames; a knob edited by hand between
// steps cancels, and the measured knob goes back to its after value.
TEST(ChangeMeasurement, InterleavesTheSidesOnTheRunnerAndEndsOnTheAfterValues) {
    auto session = test::makeSession(32, 18);
    session->loadScene("spheres");
    KnobRegistry& knobs = session->knobs();
    const int samples = *knobs.find("ssao.samples");
    knobs.set(samples, 16);
    session->render();
    knobs.set(samples, 64);
    const KnobChange change{{samples}, {16.0}, {64.0}, "ssao.samples 16 -> 64"};
    ChangeMeasurement m;
    m.start(change, {3, 1, 1}, {"ao"});
    // Turns of 1 settling + 1 counted frame, before then after, 3 counted a side.
    EXPECT_EQ(m.framesScheduled(), 12);
    std::vector<double> seen;
    int steps = 0;
    while (m.active()) {
        ASSERT_LT(++steps, 20);
        m.step(*session);
        seen.push_back(knobs.value(samples));
    }
    EXPECT_EQ(steps, 12);
    EXPECT_EQ(m.state(), ChangeMeasurement::State::Done) << m.status();
    // Between steps the view's value, 64, always.
    EXPECT_EQ(seen, std::vector<double>(12, 64.0));
    const PassVerdict* ao = m.verdict().find("ao");
    ASSERT_NE(ao, nullptr);
    EXPECT_EQ(ao->beforeFrames, 3);
    EXPECT_EQ(ao->afterFrames, 3);
    EXPECT_TRUE(ao->influenced);
    const PassVerdict* geometry = m.verdict().find("geometry");
    ASSERT_NE(geometry, nullptr);
    EXPECT_FALSE(geometry->influenced);
    EXPECT_EQ(m.verdict().passes.back().pass, PassTimer::kFrameSeries);

    // A knob edited by hand between steps cancels; the measured knob is at its after value.
    m.start(change, {3, 1, 1}, {"ao"});
    ASSERT_TRUE(m.step(*session));
    EXPECT_EQ(knobs.value(samples), 64.0);
    knobs.set(*knobs.find("bloom.enabled"), 0.0);
    EXPECT_FALSE(m.step(*session));
    EXPECT_EQ(m.state(), ChangeMeasurement::State::Cancelled);
    EXPECT_EQ(m.status(), "cancelled: a knob changed during the measurement");
    EXPECT_EQ(knobs.value(samples), 64.0);
}
