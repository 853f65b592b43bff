// Renamed knobs and values (issue 22): ssao.enabled is ao.enabled and
// lighting.ambient_occlusion's value ssao is screen; the old spellings still
// set the new knob from --set, a scene's settings and a preset, each time
// with a warning that names both. No GL.
#include <gtest/gtest.h>

#include <algorithm>

#include "renderer/Error.h"
#include "renderer/RunConfig.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/knobs/Preset.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

// Collects the alias warnings while it lives.
struct Warnings {
    std::vector<std::string> said;
    KnobRegistry::WarningHandler previous;
    Warnings() {
        previous = KnobRegistry::setWarningHandler([this](const std::string& w) { said.push_back(w); });
    }
    ~Warnings() { KnobRegistry::setWarningHandler(previous); }
    bool contains(const std::string& text) const {
        for (const auto& w : said)
            if (w.find(text) != std::string::npos) return true;
        return false;
    }
};

bool flag(const KnobRegistry& k, const std::string& name) { return k.value(*k.find(name)) != 0.0; }

}  // namespace

TEST(KnobAlias, TheOldKnobNameSetsTheNewOneAndWarns) {
    KnobRegistry k = RunConfig::declaredKnobs();
    Warnings w;
    ASSERT_TRUE(flag(k, "ao.enabled"));
    k.applyAssignment("ssao.enabled=false");
    EXPECT_FALSE(flag(k, "ao.enabled"));
    ASSERT_EQ(w.said.size(), 1u);
    EXPECT_EQ(w.said[0], "knob 'ssao.enabled' is now 'ao.enabled' (AO has several methods now, chosen by ao.method); "
                         "the old name still works");
    EXPECT_FALSE(k.find("ssao.enabled"));  // not a knob of its own
    // A bad value under the old name is refused under the new one's rules.
    EXPECT_THROW(k.applyAssignment("ssao.enabled=maybe"), Error);
}

TEST(KnobAlias, TheOldValueSetsTheNewOneAndWarns) {
    KnobRegistry k = RunConfig::declaredKnobs();
    Warnings w;
    k.applyAssignment("lighting.ambient_occlusion=ssao");
    EXPECT_EQ(k.format(*k.find("lighting.ambient_occlusion")), "screen");
    EXPECT_TRUE(w.contains("knob 'lighting.ambient_occlusion': value 'ssao' is now 'screen'"));
    w.said.clear();
    k.applyAssignment("lighting.ambient_occlusion=baked");  // no alias, no warning
    EXPECT_TRUE(w.said.empty());
}

TEST(KnobAlias, ASceneOrPresetNamingTheOldKnobWorks) {
    const KnobRegistry declared = RunConfig::declaredKnobs();
    Warnings w;
    Scene scene;
    scene.name = scene.source = "old-names.json";
    scene.settings = {{"ssao.enabled", "false"}, {"lighting.ambient_occlusion", "ssao"}};
    KnobRegistry k = declared;
    RunConfig run;
    run.applyKnobs(k, scene);
    EXPECT_FALSE(flag(k, "ao.enabled"));
    EXPECT_EQ(k.format(*k.find("lighting.ambient_occlusion")), "screen");
    EXPECT_TRUE(w.contains("'ssao.enabled' is now 'ao.enabled'"));

    const Preset preset = Preset::fromJson(R"({"name": "old", "knobs": {"ssao.enabled": false, "ssao.samples": 8}})",
                                           "old.json");
    KnobRegistry p = declared;
    const Preset::ApplyReport r = preset.applyKnobs(p);
    EXPECT_TRUE(r.ignored.empty());
    EXPECT_EQ(r.applied, 2);
    EXPECT_FALSE(flag(p, "ao.enabled"));
    EXPECT_EQ(p.value(*p.find("ssao.samples")), 8.0);
}

// A preset naming a knob by its old and its new name would be decided by the
// file's key order: refused, in either order, both names said (a new user's find).
TEST(KnobAlias, APresetGivingTheOldAndTheNewNameIsRefusedInEitherOrder) {
    const KnobRegistry declared = RunConfig::declaredKnobs();
    for (const char* text : {R"({"name": "both", "knobs": {"ssao.enabled": false, "ao.enabled": true}})",
                             R"({"name": "both", "knobs": {"ao.enabled": true, "ssao.enabled": false}})"}) {
        const Preset preset = Preset::fromJson(text, "both.json");
        KnobRegistry k = declared;
        const double before = k.value(*k.find("ao.enabled"));
        const Preset::ApplyReport r = preset.applyKnobs(k);
        ASSERT_EQ(r.ignored.size(), 1u) << text;
        EXPECT_NE(r.ignored[0].find("knobs.ssao.enabled and knobs.ao.enabled set the same knob"), std::string::npos)
            << r.ignored[0];
        EXPECT_EQ(r.applied, 0);
        EXPECT_EQ(k.value(*k.find("ao.enabled")), before);  // nothing applied
    }
}

// Issue 23: --sweep (and a Python sweep dict) takes the old knob name: the
// axis is the new knob, named by the new name, with --set's warning.
TEST(KnobAlias, ASweepOfTheOldKnobNameSweepsTheNewOne) {
    Warnings w;
    TradeoffOptions o;
    o.run.width = 64;
    o.run.height = 48;
    o.sweep.axes = {{"ssao.enabled", {"true", "false"}}};
    const TradeoffRunner runner(o);
    ASSERT_EQ(runner.options().sweep.axes.size(), 1u);
    EXPECT_EQ(runner.options().sweep.axes[0].name, "ao.enabled");
    EXPECT_EQ(runner.points().size(), 2u);
    EXPECT_TRUE(w.contains("knob 'ssao.enabled' is now 'ao.enabled'"));
    // The old and the new name together are one axis given twice.
    o.sweep.axes = {{"ssao.enabled", {"true"}}, {"ao.enabled", {"false"}}};
    EXPECT_THROW(TradeoffRunner{o}, Error);
}

// A sweep's values are read once, when the runner checks them: each is kept
// as the CSV writes it and as the run applies it (the number the written
// text reads back as), and each point says which value of each axis it has.
TEST(TradeoffRunner, ReadsEachAxisValueOnceAndCarriesItTyped) {
    TradeoffOptions o;
    o.run.scene = "default";
    o.run.width = 64;
    o.run.height = 48;
    o.sweep.axes = {{"ssao.radius", {"0.50", "1e0"}},
                    {"lighting.strategy", {"tiled", "volumes"}},
                    {"camera.near", {"0.1234567", "0.5"}}};
    const TradeoffRunner runner(o);
    const auto& axes = runner.options().sweep.axes;
    ASSERT_EQ(axes.size(), 3u);
    EXPECT_EQ(axes[0].values, (std::vector<std::string>{"0.5", "1"}));
    EXPECT_EQ(axes[0].numbers, (std::vector<double>{0.5, 1.0}));
    const KnobRegistry knobs = RunConfig::declaredKnobs();
    const KnobSpec& strategy = knobs.specs()[static_cast<size_t>(*knobs.find("lighting.strategy"))];
    const auto choice = [&](const std::string& c) {
        return static_cast<double>(std::find(strategy.choices.begin(), strategy.choices.end(), c) - strategy.choices.begin());
    };
    EXPECT_EQ(axes[1].numbers, (std::vector<double>{choice("tiled"), choice("volumes")}));
    // A plane is written as %.6g and applied as what that text says.
    EXPECT_EQ(axes[2].values[0], "0.123457");
    EXPECT_EQ(axes[2].numbers[0], static_cast<double>(0.123457f));
    ASSERT_EQ(runner.points().size(), 8u);
    const TradeoffPoint& last = runner.points().back();
    EXPECT_EQ(last.at, (std::vector<size_t>{1, 1, 1}));
    EXPECT_EQ(last.values, (std::vector<std::string>{"1", "volumes", "0.5"}));
}

// Issue 35: fxaa.enabled became aa.method (several anti-aliasing methods):
// true stands for aa.method=fxaa and false for none, as its bool took them
// (any case, 1/0, on/off, yes/no), in --set, a scene's settings, a preset and
// a sweep, each time warned; a bad value is still refused.
TEST(KnobAlias, FxaaEnabledIsAnOldNameForAaMethod) {
    const KnobRegistry declared = RunConfig::declaredKnobs();
    KnobRegistry k = declared;
    Warnings w;
    const int id = *k.find("aa.method");
    EXPECT_EQ(k.format(id), "fxaa");
    k.applyAssignment("fxaa.enabled=false");
    EXPECT_EQ(k.format(id), "none");
    EXPECT_TRUE(w.contains("knob 'fxaa.enabled' is now 'aa.method'")) << (w.said.empty() ? "" : w.said[0]);
    EXPECT_TRUE(w.contains("value 'false' is now 'none'"));
    for (const char* on : {"true", "TRUE", "1", "on", "Yes"}) {
        k.applyAssignment("aa.method=none");
        k.applyAssignment(std::string("fxaa.enabled=") + on);
        EXPECT_EQ(k.format(id), "fxaa") << on;
    }
    EXPECT_FALSE(k.find("fxaa.enabled"));
    EXPECT_THROW(k.applyAssignment("fxaa.enabled=maybe"), Error);

    Scene scene;
    scene.name = scene.source = "old-fxaa.json";
    scene.settings = {{"fxaa.enabled", "false"}};
    KnobRegistry fromScene = declared;
    RunConfig run;
    run.applyKnobs(fromScene, scene);
    EXPECT_EQ(fromScene.format(id), "none");

    const Preset preset = Preset::fromJson(R"({"name": "old", "knobs": {"fxaa.enabled": false}})", "old.json");
    KnobRegistry fromPreset = declared;
    const Preset::ApplyReport r = preset.applyKnobs(fromPreset);
    EXPECT_TRUE(r.ignored.empty());
    EXPECT_EQ(fromPreset.format(id), "none");

    TradeoffOptions o;
    o.run.width = 64;
    o.run.height = 48;
    o.sweep.axes = {{"fxaa.enabled", {"true", "false"}}};
    const TradeoffRunner runner(o);
    ASSERT_EQ(runner.options().sweep.axes.size(), 1u);
    EXPECT_EQ(runner.options().sweep.axes[0].name, "aa.method");
    EXPECT_EQ(runner.points().size(), 2u);
}
