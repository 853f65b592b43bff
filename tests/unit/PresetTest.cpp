#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "renderer/Error.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/knobs/Preset.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Moves every knob off its default (to another valid value).
void changeEveryKnob(KnobRegistry& k) {
    for (size_t i = 0; i < k.size(); ++i) {
        const KnobSpec& s = k.spec(static_cast<int>(i));
        const double v = k.value(static_cast<int>(i));
        if (s.type == KnobType::Bool || s.type == KnobType::Enum) k.set(static_cast<int>(i), v == s.maxValue ? s.minValue : v + 1);
        else k.set(static_cast<int>(i), v == s.maxValue ? s.minValue : (v + s.maxValue) * 0.5 + (s.type == KnobType::Int ? 1 : 0));
    }
}

}  // namespace

TEST(Preset, RoundTripRestoresEveryKnobCameraAndScene) {
    KnobRegistry knobs;
    Pipeline declarations(knobs);
    changeEveryKnob(knobs);
    Camera cam;
    cam.position = {1.5f, 2.25f, -3.0f};
    cam.target = {0.0f, 0.5f, 0.0f};
    cam.fovYDegrees = 42.0f;
    cam.nearPlane = 0.25f;
    cam.farPlane = 321.0f;
    const fs::path path = test::tempDir() / "roundtrip.json";
    Preset::capture("round trip", knobs, cam, "builtin:street").save(path.string());
    std::vector<double> saved;
    for (size_t i = 0; i < knobs.size(); ++i) saved.push_back(knobs.value(static_cast<int>(i)));

    knobs.resetAll();
    const Preset loaded = Preset::load(path.string());
    const Preset::ApplyReport r = loaded.applyKnobs(knobs);
    EXPECT_TRUE(r.ignored.empty());
    EXPECT_EQ(r.applied, static_cast<int>(knobs.size()));
    for (size_t i = 0; i < knobs.size(); ++i)
        EXPECT_NEAR(knobs.value(static_cast<int>(i)), saved[i], 1e-6 * std::max(1.0, std::fabs(saved[i])))
            << knobs.spec(static_cast<int>(i)).name;
    ASSERT_TRUE(loaded.camera);
    EXPECT_FLOAT_EQ(loaded.camera->position.y, 2.25f);
    EXPECT_FLOAT_EQ(loaded.camera->fovYDegrees, 42.0f);
    EXPECT_FLOAT_EQ(loaded.camera->farPlane, 321.0f);
    EXPECT_EQ(loaded.scene, "builtin:street");
    EXPECT_EQ(loaded.name, "round trip");
}

TEST(Preset, UnknownAndOutOfRangeKeysAreReportedAndTheRestApplied) {
    KnobRegistry knobs;
    Pipeline declarations(knobs);
    const Preset p = Preset::fromJson(R"({"knobs": {"tonemap.key": 0.3, "tonemap.kee": 0.5, "lighting.threshold": 9,
                                                  "tonemap.operator": "drago", "lighting.frustum_cull": false}})",
                                      "partial.json");
    const Preset::ApplyReport r = p.applyKnobs(knobs);
    EXPECT_EQ(r.applied, 2);
    ASSERT_EQ(r.ignored.size(), 3u);
    EXPECT_NE(r.ignored[0].find("tonemap.kee"), std::string::npos);
    EXPECT_NE(r.ignored[1].find("out of range"), std::string::npos);
    EXPECT_NE(r.ignored[2].find("drago"), std::string::npos);
    EXPECT_FLOAT_EQ(static_cast<float>(knobs.value(*knobs.find("tonemap.key"))), 0.3f);
    EXPECT_FLOAT_EQ(static_cast<float>(knobs.value(*knobs.find("lighting.threshold"))), static_cast<float>(1.0 / 255.0));
}

TEST(Preset, CorruptFileChangesNothingAndStaysIntact) {
    KnobRegistry knobs;
    Pipeline declarations(knobs);
    knobs.setFromString("tonemap.key", "0.4");
    const fs::path path = test::tempDir() / "corrupt.json";
    const std::string garbage = "{\"knobs\": {\"tonemap.key\": 0.9,,,";
    std::ofstream(path) << garbage;
    EXPECT_THROW(Preset::load(path.string()), FileError);
    EXPECT_FLOAT_EQ(static_cast<float>(knobs.value(*knobs.find("tonemap.key"))), 0.4f);
    EXPECT_EQ(readAll(path), garbage);
    std::ofstream(path) << R"({"name": "no knobs here"})";
    EXPECT_THROW(Preset::load(path.string()), FileError);
    std::ofstream(path) << R"({"knobs": {}, "camera": {"pos": [0, 1], "look-at": [0, 0, 0]}})";
    EXPECT_THROW(Preset::load(path.string()), FileError);
}

TEST(Preset, FailedSaveKeepsThePreviousFile) {
    KnobRegistry knobs;
    Pipeline declarations(knobs);
    const fs::path dir = test::tempDir() / "presets";
    fs::create_directories(dir);
    const fs::path path = dir / "keep.json";
    Preset::capture("keep", knobs, Camera{}, "default").save(path.string());
    const std::string before = readAll(path);
    // A save that cannot complete: the target name is taken by a folder...
    fs::create_directories(dir / "taken.json");
    EXPECT_THROW(Preset::capture("x", knobs, Camera{}, "").save((dir / "taken.json").string()), FileError);
    // ...or its folder is gone.
    EXPECT_THROW(Preset::capture("x", knobs, Camera{}, "").save((dir / "missing" / "keep.json").string()), FileError);
    EXPECT_EQ(readAll(path), before);
    // A good save replaces the file whole and leaves no temporary behind.
    knobs.setFromString("tonemap.key", "0.5");
    Preset::capture("keep", knobs, Camera{}, "default").save(path.string());
    EXPECT_NE(readAll(path), before);
    EXPECT_NE(readAll(path).find("\"tonemap.key\": 0.5"), std::string::npos);
    for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(Preset, BuiltinPresetsUseOnlyDeclaredKnobsWithValidValues) {
    KnobRegistry knobs;
    Pipeline declarations(knobs);
    ASSERT_FALSE(builtinPresets().empty());
    for (const Preset& p : builtinPresets()) {
        KnobRegistry copy = knobs;
        const Preset::ApplyReport r = p.applyKnobs(copy);
        EXPECT_TRUE(r.ignored.empty()) << p.name << ": " << (r.ignored.empty() ? "" : r.ignored[0]);
        EXPECT_EQ(r.applied, static_cast<int>(p.knobs.size())) << p.name;
        EXPECT_EQ(findBuiltinPreset(p.name), &p);
    }
}
