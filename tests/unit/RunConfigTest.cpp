// The run configuration's rules, with no GL: which scene opens, and the order
// in which knob values are laid over each other at every scene load.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "renderer/Error.h"
#include "renderer/RunConfig.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

// Four knobs, one for each layer to be the last to touch.
KnobRegistry fourKnobs() {
    KnobRegistry k;
    k.addFloat("a.untouched", 1.0, 0.0, 10.0, "a", "left at its default");
    k.addFloat("a.scene", 1.0, 0.0, 10.0, "a", "set by the scene");
    k.addFloat("a.preset", 1.0, 0.0, 10.0, "a", "set by the scene and the preset");
    k.addEnum("a.set", {"x", "y", "z"}, 0, "a", "set by all three");
    return k;
}

double value(const KnobRegistry& k, const std::string& name) { return k.value(*k.find(name)); }

Scene sceneWith(const std::string& source, std::vector<std::pair<std::string, std::string>> settings) {
    Scene s;
    s.name = source;
    s.source = source;
    s.camera.position = {1.0f, 2.0f, 3.0f};
    s.settings = std::move(settings);
    return s;
}

Preset presetWith(const std::string& scene, std::vector<std::pair<std::string, std::string>> knobs) {
    Preset p;
    p.name = "test preset";
    p.scene = scene;
    p.knobs = std::move(knobs);
    Camera c;
    c.position = {7.0f, 8.0f, 9.0f};
    p.camera = c;
    return p;
}

}  // namespace

TEST(RunConfig, KnobsAreDefaultsThenSceneThenPresetThenSet) {
    RunConfig run;
    run.setPreset(presetWith("", {{"a.preset", "3"}, {"a.set", "y"}}));
    run.sets = {"a.set=z"};
    const Scene scene = sceneWith("a.json", {{"a.scene", "2"}, {"a.preset", "2"}, {"a.set", "x"}});
    KnobRegistry knobs = fourKnobs();
    // Values left from an earlier scene must not survive the load.
    knobs.setFromString("a.untouched", "9");
    run.applyKnobs(knobs, scene);
    EXPECT_EQ(value(knobs, "a.untouched"), 1.0);
    EXPECT_EQ(value(knobs, "a.scene"), 2.0);
    EXPECT_EQ(value(knobs, "a.preset"), 3.0);
    EXPECT_EQ(knobs.choice(EnumKnob{*knobs.find("a.set")}), "z");

    // Another scene without settings: back to the defaults, preset and --set still apply.
    run.applyKnobs(knobs, sceneWith("b.json", {}));
    EXPECT_EQ(value(knobs, "a.scene"), 1.0);
    EXPECT_EQ(value(knobs, "a.preset"), 3.0);
    EXPECT_EQ(knobs.choice(EnumKnob{*knobs.find("a.set")}), "z");

    // --set applies in the order given.
    run.sets = {"a.set=y", "a.set=x"};
    run.applyKnobs(knobs, scene);
    EXPECT_EQ(knobs.choice(EnumKnob{*knobs.find("a.set")}), "x");
}

TEST(RunConfig, SceneArgumentBeatsThePresetsScene) {
    RunConfig run;
    EXPECT_EQ(run.sceneSpec(), "default");
    run.setPreset(presetWith("street", {}));
    EXPECT_EQ(run.sceneSpec(), "street");
    run.scene = "spheres";
    EXPECT_EQ(run.sceneSpec(), "spheres");
    // A preset without a scene leaves the default.
    RunConfig anyScene;
    anyScene.setPreset(presetWith("", {}));
    EXPECT_EQ(anyScene.sceneSpec(), "default");
}

TEST(RunConfig, ThePresetsCameraOnlyOnItsOwnScene) {
    RunConfig run;
    run.setPreset(presetWith("street", {}));
    const Scene street = sceneWith("builtin:street", {});
    const Scene spheres = sceneWith("builtin:spheres", {});
    EXPECT_EQ(run.camera(street).position, glm::vec3(7.0f, 8.0f, 9.0f));
    EXPECT_EQ(run.camera(spheres).position, glm::vec3(1.0f, 2.0f, 3.0f));
    // A preset that names no scene brings its camera to any scene.
    RunConfig anyScene;
    anyScene.setPreset(presetWith("", {}));
    EXPECT_EQ(anyScene.camera(spheres).position, glm::vec3(7.0f, 8.0f, 9.0f));
    // Without a preset: the scene's camera.
    EXPECT_EQ(RunConfig().camera(spheres).position, glm::vec3(1.0f, 2.0f, 3.0f));
}

TEST(RunConfig, NamesSceneByBuiltinNameOrAnyPathToTheFile) {
    EXPECT_TRUE(RunConfig::namesScene("street", sceneWith("builtin:street", {})));
    EXPECT_TRUE(RunConfig::namesScene("builtin:street", sceneWith("builtin:street", {})));
    EXPECT_FALSE(RunConfig::namesScene("spheres", sceneWith("builtin:street", {})));
    EXPECT_FALSE(RunConfig::namesScene("", sceneWith("", {})));
    const fs::path dir = test::tempDir() / "runconfig";
    fs::create_directories(dir / "sub");
    std::ofstream(dir / "s.json") << "{}";
    EXPECT_TRUE(RunConfig::namesScene((dir / "sub" / ".." / "s.json").string(), sceneWith((dir / "s.json").string(), {})));
}

TEST(RunConfig, ValidationNamesEveryBadPresetKeyAndTheBadSet) {
    const KnobRegistry declared = fourKnobs();
    RunConfig run;
    run.setPreset(presetWith("", {{"a.presett", "3"}, {"a.scene", "11"}, {"a.preset", "2"}}));
    try {
        run.validate(declared);
        FAIL() << "a preset with bad keys passed";
    } catch (const FileError& e) {
        EXPECT_EQ(e.path(), "test preset");
        const std::string what = e.what();
        EXPECT_NE(what.find("a.presett"), std::string::npos) << what;
        EXPECT_NE(what.find("out of range"), std::string::npos) << what;
    }
    RunConfig sets;
    sets.sets = {"a.scene=2", "a.sene=3"};
    try {
        sets.validate(declared);
        FAIL() << "a bad --set passed";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean 'a.scene'"), std::string::npos) << e.what();
    }
    sets.sets = {"a.scene=2"};
    EXPECT_NO_THROW(sets.validate(declared));
    // A bad scene setting names the scene file.
    KnobRegistry knobs = declared;
    try {
        sets.applyKnobs(knobs, sceneWith("bad.json", {{"a.scene", "-1"}}));
        FAIL() << "a bad scene setting passed";
    } catch (const FileError& e) {
        EXPECT_EQ(e.path(), "bad.json");
    }
}

TEST(RunConfig, PresetsByBuiltinNameOrFile) {
    RunConfig run;
    run.setPreset("SSAO1");
    ASSERT_NE(run.preset(), nullptr);
    EXPECT_EQ(run.preset()->name, "SSAO1");
    EXPECT_NO_THROW(run.validate());  // against the pipeline's own knobs
    EXPECT_THROW(run.setPreset("NoSuchPreset"), Error);
    const fs::path file = test::tempDir() / "runconfig-preset.json";
    std::ofstream(file) << R"({"name": "from a file", "scene": "street", "knobs": {"tonemap.key": 0.3}})";
    run.setPreset(file.string());
    EXPECT_EQ(run.preset()->name, "from a file");
    EXPECT_EQ(run.presetSpec(), file.string());
    EXPECT_EQ(run.sceneSpec(), "street");
    run.setPreset("");
    EXPECT_EQ(run.preset(), nullptr);
    EXPECT_EQ(run.sceneSpec(), "default");
}

TEST(RunConfig, RepeatedPresetsApplyInOrderKnobByKnob) {
    const fs::path dir = test::tempDir() / "run-config-presets";
    fs::create_directories(dir);
    Preset first = presetWith("street", {{"a.preset", "3"}, {"a.set", "y"}});
    first.name = "first";
    first.groups = {"a"};
    Preset second = presetWith("", {{"a.preset", "4"}});
    second.name = "second";
    second.camera.reset();
    second.groups = {"b"};
    first.save((dir / "first.json").string());
    second.save((dir / "second.json").string());
    RunConfig run;
    run.addPreset((dir / "first.json").string());
    run.addPreset((dir / "second.json").string());
    ASSERT_NE(run.preset(), nullptr);
    EXPECT_EQ(run.preset()->name, "first + second");
    EXPECT_EQ(run.presetSpecs().size(), 2u);
    EXPECT_EQ(run.presetSpec(), (dir / "first.json").string() + " + " + (dir / "second.json").string());
    EXPECT_EQ(run.preset()->groups, (std::vector<std::string>{"a", "b"}));
    // The scene and camera: the last preset that has one.
    EXPECT_EQ(run.sceneSpec(), "street");
    KnobRegistry knobs = fourKnobs();
    run.applyKnobs(knobs, sceneWith("builtin:street", {}));
    EXPECT_EQ(value(knobs, "a.preset"), 4.0);  // the later preset's
    EXPECT_EQ(value(knobs, "a.set"), 1.0);     // y, only the first sets it
    EXPECT_EQ(run.camera(sceneWith("builtin:street", {})).position, glm::vec3(7.0f, 8.0f, 9.0f));
    // The other way round the first one's a.preset wins.
    RunConfig reversed;
    reversed.addPreset((dir / "second.json").string());
    reversed.addPreset((dir / "first.json").string());
    KnobRegistry again = fourKnobs();
    reversed.applyKnobs(again, sceneWith("builtin:street", {}));
    EXPECT_EQ(value(again, "a.preset"), 3.0);
    // setPreset replaces them all; "" clears.
    run.setPreset((dir / "second.json").string());
    EXPECT_EQ(run.preset()->name, "second");
    run.setPreset("");
    EXPECT_EQ(run.preset(), nullptr);
    EXPECT_TRUE(run.presetSpecs().empty());
}
