#include <gtest/gtest.h>

#include "renderer/graph/ChangeCost.h"
#include "renderer/graph/PassTimer.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/knobs/KnobRegistry.h"

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

namespace {

// Synthetic GPU times: `ms` with a spread of about +-`noise` ms (a fixed,
// irregular sequence, the same every run).
std::vector<double> noisy(double ms, double noise, int n, int seed) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(ms + noise * static_cast<double>(((i + seed) * 37) % 11 - 5) / 5.0);
    return v;
}

KnobRegistry ssaoKnobs() {
    KnobRegistry k;
    k.addInt("ssao.samples", 16, 4, 64, "ssao", "samples");
    k.addFloat("ssao.radius", 1.0, 0.01, 20.0, "ssao", "radius");
    k.addBool("bloom.enabled", true, "bloom", "bloom");
    return k;
}

}  // namespace

// The change is what the user committed: typing 64 into the samples field
// goes through 6 while the field is active, and only 16 -> 64 is reported,
// once, when the edit ends.
TEST(ChangeCost, AChangeIsTheCommittedValueNotEachKeystroke) {
    KnobRegistry knobs = ssaoKnobs();
    const int samples = *knobs.find("ssao.samples");
    KnobChangeWatcher w;
    w.reset(knobs);
    EXPECT_FALSE(w.update(knobs, false));
    knobs.set(samples, 6);  // "6" typed
    EXPECT_FALSE(w.update(knobs, true));
    knobs.set(samples, 64);  // "64"
    EXPECT_FALSE(w.update(knobs, true));
    const auto c = w.update(knobs, false);  // Enter: the field is let go
    ASSERT_TRUE(c);
    EXPECT_EQ(c->what, "ssao.samples 16 -> 64");
    ASSERT_EQ(c->knobs, std::vector<int>{samples});
    EXPECT_EQ(c->before, std::vector<double>{16.0});
    EXPECT_EQ(c->after, std::vector<double>{64.0});
    EXPECT_EQ(w.committed()[static_cast<size_t>(samples)], 64.0);
    EXPECT_FALSE(w.update(knobs, false)) << "reported twice";
    // Dragged away and back to where it was: no change.
    knobs.set(samples, 30);
    EXPECT_FALSE(w.update(knobs, true));
    knobs.set(samples, 64);
    EXPECT_FALSE(w.update(knobs, false));
    // Two knobs at once (reset group): both, named as the first and a count.
    knobs.set(samples, 8);
    knobs.set(*knobs.find("ssao.radius"), 2.0);
    const auto two = w.update(knobs, false);
    ASSERT_TRUE(two);
    EXPECT_EQ(two->what, "ssao.samples 64 -> 8 and 1 more");
    EXPECT_EQ(two->knobs.size(), 2u);
}

// What a knob can reach: its readers and everything downstream of them.
TEST(ChangeCost, APassUpstreamOfOrBesideTheReaderIsNotInfluenced) {
    const std::vector<PassEdges> passes = {
        {"geometry", {}, {"gbuffer.depth", "gbuffer.normal"}},
        {"ssao", {"gbuffer.depth", "gbuffer.normal"}, {"ssao.raw"}},
        {"ssao_blur", {"ssao.raw"}, {"ssao.blurred"}},
        {"lights", {}, {"lights.table"}},
        {"shadows", {"lights.table"}, {"lights.table", "shadow.maps"}},
        {"lighting", {"gbuffer.depth", "lights.table", "ssao.blurred"}, {"lbuffer"}},
        {"bloom", {"lbuffer"}, {"bloom.result"}},
        {"tonemap", {"lbuffer", "bloom.result"}, {"tonemap.result"}},
    };
    EXPECT_EQ(influencedPasses(passes, {"ssao"}), (std::set<std::string>{"ssao", "ssao_blur", "lighting", "bloom", "tonemap"}));
    EXPECT_EQ(influencedPasses(passes, {"lights"}),
              (std::set<std::string>{"lights", "shadows", "lighting", "bloom", "tonemap"}));
    EXPECT_EQ(influencedPasses(passes, {"tonemap"}), (std::set<std::string>{"tonemap"}));
    EXPECT_EQ(influencedPasses(passes, {"*"}).size(), passes.size());
    EXPECT_TRUE(seriesInfluenced("lighting/shadow maps", {"lighting"}));
    EXPECT_FALSE(seriesInfluenced("geometry", {"lighting"}));
    EXPECT_TRUE(seriesInfluenced(PassTimer::kFrameSeries, {"lighting"}));
}

// The verdict from synthetic samples: ssao 70 -> 114 ms is flagged at the
// adjusted level; bloom, which an SSAO change cannot reach, is shown but not
// flagged though its frames came out 49% slower (a busy CPU); tonemap,
// influenced but unchanged within its noise, is not flagged either.
TEST(ChangeCost, TheVerdictFlagsTheAffectedPassAndNotAnUnreachableOneWithNoise) {
    SeriesSamples before, after;
    before["geometry"] = noisy(20.0, 1.0, 24, 0);
    after["geometry"] = noisy(20.0, 1.0, 24, 3);
    before["ssao"] = noisy(70.0, 2.0, 24, 1);
    after["ssao"] = noisy(114.0, 2.0, 24, 4);
    before["bloom"] = noisy(10.0, 0.5, 24, 2);
    after["bloom"] = noisy(14.9, 0.5, 24, 5);  // +49%, but bloom reads nothing ssao writes here
    before["tonemap"] = noisy(2.0, 0.2, 24, 6);
    after["tonemap"] = noisy(2.0, 0.2, 24, 7);
    before["frame"] = noisy(102.0, 3.0, 24, 8);
    after["frame"] = noisy(150.9, 3.0, 24, 9);
    after["ssao_blur"] = std::vector<double>(24, 3.0);  // switched on by the change
    const std::set<std::string> influenced = {"ssao", "ssao_blur", "lighting", "tonemap"};
    const ChangeVerdict v = judgeChange(before, after, influenced, {"geometry", "ssao", "ssao_blur", "bloom", "tonemap", "frame"});
    ASSERT_EQ(v.passes.size(), 6u);
    EXPECT_EQ(v.passes[0].pass, "geometry");
    EXPECT_EQ(v.passes[5].pass, "frame");
    // ssao, tonemap and frame are compared (ssao_blur has no frames before).
    EXPECT_EQ(v.compared, 3);
    EXPECT_NEAR(v.perPassConfidence, 1.0 - 0.05 / 3.0, 1e-12);
    EXPECT_EQ(v.notInfluenced, 2);
    const PassVerdict& ssao = *v.find("ssao");
    EXPECT_TRUE(ssao.influenced);
    EXPECT_TRUE(ssao.significant);
    EXPECT_NEAR(ssao.beforeMs, 70.0, 1e-9);
    EXPECT_NEAR(ssao.afterMs, 114.0, 1e-9);
    EXPECT_EQ(ssao.beforeFrames, 24);
    EXPECT_GT(ssao.ratio.low, 1.5);
    EXPECT_EQ(ssao.describe().substr(0, 9), "+44.0 ms ") << ssao.describe();
    EXPECT_NE(ssao.describe().find("98.3% CI"), std::string::npos) << ssao.describe();
    const PassVerdict& bloom = *v.find("bloom");
    EXPECT_FALSE(bloom.influenced);
    EXPECT_FALSE(bloom.significant) << "a pass the change cannot reach was flagged";
    EXPECT_GT(bloom.ratio.low, 1.3) << "its own interval is still reported";
    EXPECT_NE(bloom.describe().find("95% CI"), std::string::npos);
    EXPECT_FALSE(v.find("geometry")->significant);
    EXPECT_FALSE(v.find("tonemap")->significant) << v.find("tonemap")->describe();
    EXPECT_TRUE(v.find("frame")->significant);
    EXPECT_EQ(v.find("ssao_blur")->describe(), "new: 3.000 ms");
    EXPECT_FALSE(v.find("ssao_blur")->significant);
    EXPECT_NE(v.method().find("Bonferroni over 3"), std::string::npos) << v.method();
}

// With 20 unchanged, noisy passes compared, the adjusted intervals flag none
// of them; at 95% each, one in twenty would be flagged by chance.
TEST(ChangeCost, ManyUnchangedPassesAreNotFlaggedByChance) {
    SeriesSamples before, after;
    std::set<std::string> influenced;
    for (int p = 0; p < 20; ++p) {
        const std::string n = "pass" + std::to_string(p);
        // Each side its own irregular noise (a different order of the same spread plus a little drift).
        std::vector<double> b, a;
        for (int i = 0; i < 16; ++i) {
            b.push_back(10.0 + static_cast<double>((i * 7 + p * 3) % 13 - 6) * 0.25);
            a.push_back(10.0 + static_cast<double>((i * 5 + p * 11) % 13 - 6) * 0.25 + 0.05 * ((p % 3) - 1));
        }
        before[n] = b;
        after[n] = a;
        influenced.insert(n);
    }
    const ChangeVerdict v = judgeChange(before, after, influenced);
    EXPECT_EQ(v.compared, 20);
    for (const auto& p : v.passes) EXPECT_FALSE(p.significant) << p.pass << ": " << p.describe();
}

// The pipeline learns which pass reads each knob while it makes and connects
// the passes (no GL): the declaring pass, and passes that look a knob up.
TEST(ChangeCost, ThePipelineKnowsWhichPassesReadEachKnob) {
    KnobRegistry knobs;
    Pipeline pipeline(knobs);
    auto readers = [&](const std::string& knob) { return pipeline.knobReaders(*knobs.find(knob)); };
    EXPECT_EQ(readers("ssao.samples"), std::set<std::string>{"ao"});
    // Declared by the light table pass, though its group is "lighting".
    EXPECT_EQ(readers("lighting.threshold"), std::set<std::string>{"lights"});
    // Looked up by other passes: bloom (upstream of tonemap) reads tonemap.nan_guard.
    EXPECT_TRUE(readers("tonemap.nan_guard").count("bloom"));
    EXPECT_TRUE(readers("tonemap.nan_guard").count("tonemap"));
    EXPECT_TRUE(readers("lighting.directional_in_gbuffer").count("geometry"));
    EXPECT_TRUE(readers("lighting.directional_in_gbuffer").count("lighting"));
    EXPECT_TRUE(readers("depth.mode").count("*")) << "the camera every pass uses";
    // With the pass edges: an SSAO change cannot reach the geometry or the light table.
    const std::set<std::string> ssao = passesReachedBy(pipeline, {*knobs.find("ssao.samples")});
    EXPECT_TRUE(ssao.count("ao") && ssao.count("ao_filter") && ssao.count("lighting") && ssao.count("tonemap"));
    EXPECT_FALSE(ssao.count("geometry") || ssao.count("lights") || ssao.count("shadows") || ssao.count("skybox"));
    EXPECT_EQ(passesReachedBy(pipeline, {*knobs.find("depth.mode")}).size(), pipeline.passList().size());
    // lighting.threshold reaches the light table and what follows it, not the G-buffer or SSAO.
    const std::set<std::string> threshold = passesReachedBy(pipeline, {*knobs.find("lighting.threshold")});
    EXPECT_TRUE(threshold.count("lights") && threshold.count("shadows") && threshold.count("lighting"));
    EXPECT_FALSE(threshold.count("geometry") || threshold.count("ao"));
}
