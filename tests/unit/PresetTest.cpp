#include <gtest/gtest.h>

#include <cctype>

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

TEST(Preset, SaveLoadSaveIsByteIdenticalAndNothingReadsBackChanged) {
    KnobRegistry knobs;
    Pipeline declarations(knobs);
    changeEveryKnob(knobs);
    // Values a slider or an orbit leaves behind: floats whose double text is noisy.
    knobs.set(*knobs.find("lighting.threshold"), 1.0 / 255.0);
    Camera cam;
    cam.position = {0.1f, -13.999999f, 1.0f / 3.0f};
    cam.target = {2.0f / 7.0f, 0.5f, 1e-7f};
    cam.fovYDegrees = 47.123456f;
    cam.nearPlane = 0.1f;
    cam.farPlane = 1234.5677f;
    const fs::path first = test::tempDir() / "exact-1.json", second = test::tempDir() / "exact-2.json";
    Preset::capture("exact", knobs, cam, "builtin:street").save(first.string());

    KnobRegistry reloaded;
    Pipeline declarations2(reloaded);
    const Preset p = Preset::load(first.string());
    EXPECT_TRUE(p.applyKnobs(reloaded).ignored.empty());
    for (size_t i = 0; i < knobs.size(); ++i)
        EXPECT_EQ(reloaded.value(static_cast<int>(i)), knobs.value(static_cast<int>(i))) << knobs.spec(static_cast<int>(i)).name;
    ASSERT_TRUE(p.camera);
    EXPECT_EQ(p.camera->position, cam.position);
    EXPECT_EQ(p.camera->target, cam.target);
    EXPECT_EQ(p.camera->fovYDegrees, cam.fovYDegrees);
    EXPECT_EQ(p.camera->farPlane, cam.farPlane);
    Preset::capture("exact", reloaded, *p.camera, "builtin:street").save(second.string());
    EXPECT_EQ(readAll(first), readAll(second));

    // Integers as integers, floats in their shortest form.
    const std::string text = readAll(first);
    const int samples = static_cast<int>(knobs.value(*knobs.find("ssao.samples")));
    EXPECT_NE(text.find("\"ssao.samples\": " + std::to_string(samples) + ",\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\"lighting.threshold\": 0.003921569,"), std::string::npos) << text;
    EXPECT_NE(text.find("-13.999999,"), std::string::npos) << text;
    EXPECT_EQ(text.find("99999904"), std::string::npos) << text;

    // A default written and read back is still the default (not "changed").
    KnobRegistry defaults;
    Pipeline declarations3(defaults);
    const fs::path d = test::tempDir() / "exact-defaults.json";
    Preset::capture("defaults", defaults, cam, "").save(d.string());
    Preset::load(d.string()).applyKnobs(defaults);
    for (size_t i = 0; i < defaults.size(); ++i) EXPECT_TRUE(defaults.isDefault(static_cast<int>(i))) << defaults.spec(static_cast<int>(i)).name;
}

TEST(Preset, LoadingAPresetGivesTheSameKnobsWhateverWasLoadedBefore) {
    const std::vector<std::pair<std::string, std::string>> sceneSettings = {{"ssao.radius", "0.75"}, {"bloom.threshold", "3"}};
    auto after = [&](const Preset* before, const Preset& p) {
        KnobRegistry k;
        Pipeline declarations(k);
        for (const auto& [n, v] : sceneSettings) k.setFromString(n, v);
        if (before) before->applyOver(k, sceneSettings);
        EXPECT_TRUE(p.applyOver(k, sceneSettings).ignored.empty());
        std::vector<double> values;
        for (size_t i = 0; i < k.size(); ++i) values.push_back(k.value(static_cast<int>(i)));
        return values;
    };
    const Preset* low = findBuiltinPreset("Low");
    const Preset* high = findBuiltinPreset("High");
    const Preset* ssao5 = findBuiltinPreset("SSAO5");
    const Preset* coarse = findBuiltinPreset("lights: coarse (threshold 5/256)");
    ASSERT_TRUE(low && high && ssao5 && coarse);
    // A saved (full) preset with everything moved.
    KnobRegistry moved;
    Pipeline declarations(moved);
    changeEveryKnob(moved);
    const Preset everything = Preset::capture("everything", moved, Camera{}, "");

    for (const Preset* b : {low, high, ssao5}) {
        const auto fresh = after(nullptr, *b);
        for (const Preset* a : {low, high, ssao5, coarse, &everything}) EXPECT_EQ(after(a, *b), fresh) << b->name << " after " << a->name;
    }
    // SSAO5 after Low does not keep Low's shadow map size, and the scene's settings come back.
    KnobRegistry k;
    Pipeline d2(k);
    low->applyOver(k, sceneSettings);
    ssao5->applyOver(k, sceneSettings);
    EXPECT_EQ(k.value(*k.find("shadows.map_size")), k.spec(*k.find("shadows.map_size")).defaultValue);
    EXPECT_EQ(k.value(*k.find("bloom.threshold")), 3.0);
    // A partial preset changes only its groups: the quality level before it stays.
    coarse->applyOver(k, sceneSettings);
    EXPECT_EQ(k.value(*k.find("ssao.samples")), 32.0);
    EXPECT_FLOAT_EQ(static_cast<float>(k.value(*k.find("lighting.threshold"))), 5.0f / 256.0f);
    EXPECT_FALSE(coarse->covers("ssao.samples"));
    EXPECT_TRUE(coarse->covers("lighting.strategy"));
}

// A preset named for an AO method renders that method, whatever the scene's
// settings or an earlier preset chose (SSAO3 over a scene with ao.method=gtao
// rendered GTAO, and --preset AOV3 --preset SSAO3 rendered AOV).
TEST(Preset, EveryBuiltinPresetOfAnAoMethodPinsThatMethod) {
    const std::vector<std::pair<std::string, std::string>> sceneSettings = {{"ao.method", "gtao"}};
    for (const Preset& p : builtinPresets()) {
        // Named for a method (SSAO1-5, GTAO low..ultra, AOV1-3); the quality
        // levels Low/Medium/High leave the method alone (PresetOrderCli).
        std::string family;
        for (const char* m : {"SSAO", "GTAO", "AOV"})
            if (p.name.rfind(m, 0) == 0) family = m;
        if (family.empty()) continue;
        for (char& c : family) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        for (const char* before : {"AOV3", "GTAO high", "SSAO1"}) {
            KnobRegistry k;
            Pipeline declarations(k);
            for (const auto& [n, v] : sceneSettings) k.setFromString(n, v);
            findBuiltinPreset(before)->applyOver(k, sceneSettings);
            p.applyOver(k, sceneSettings);
            EXPECT_EQ(k.format(*k.find("ao.method")), family) << p.name << " after " << before;
        }
    }
}

// Issue 32: the quality levels follow seed 002 section 7's list, its
// stencil-routed A-buffer included (4 / 8 / 8 samples per pixel), and say
// that its resolutions are render sizes, which a preset cannot set.
TEST(Preset, QualityLevelsSetTheSeedsABufferAndSayTheyCannotSetTheRenderSize) {
    const std::pair<const char*, double> levels[] = {{"Low", 4}, {"Medium", 8}, {"High", 8}};
    for (const auto& [name, samples] : levels) {
        const Preset* p = findBuiltinPreset(name);
        ASSERT_TRUE(p) << name;
        KnobRegistry k;
        Pipeline declarations(k);
        k.setFromString("oit.method", "weighted");
        EXPECT_TRUE(p->applyOver(k, {}).ignored.empty()) << name;
        EXPECT_EQ(k.format(*k.find("oit.method")), "abuffer") << name;
        EXPECT_EQ(k.value(*k.find("oit.samples")), samples) << name;
        EXPECT_NE(p->description.find("render size, not set by a preset: --size or the window"), std::string::npos)
            << p->description;
    }
}

// Issue 36: seed 000 section 6.5's whole system as a built-in preset: SSAO3
// (half size, 16 samples, world radius 1, bilateral blur 20), the
// stencil-routed A-buffer at 8 samples, Reinhard, a 2048^2 shadow map, on the
// atrium scene; every other knob back to its default whatever came before.
TEST(Preset, OverallSetsSeed000Section65sKnobsOnTheAtrium) {
    const Preset* p = findBuiltinPreset("Overall");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->scene, "atrium");
    EXPECT_TRUE(p->groups.empty());  // covers every group, as the quality levels do
    KnobRegistry k;
    Pipeline declarations(k);
    k.setFromString("ao.method", "gtao");
    k.setFromString("tonemap.operator", "aces");
    k.setFromString("shadows.enabled", "false");
    k.setFromString("bloom.threshold", "7");
    EXPECT_TRUE(p->applyOver(k, {}).ignored.empty());
    const std::pair<const char*, const char*> expected[] = {
        {"ao.enabled", "true"},         {"ao.method", "ssao"},           {"ssao.resolution", "half"},
        {"ssao.samples", "16"},         {"ssao.radius", "1"},            {"ssao.radius_unit", "world"},
        {"ssao_blur.mode", "bilateral"}, {"ssao_blur.width", "20"},      {"oit.method", "abuffer"},
        {"oit.samples", "8"},           {"tonemap.operator", "reinhard"}, {"shadows.enabled", "true"},
        {"shadows.map_size", "2048"}};
    for (const auto& [name, value] : expected) EXPECT_EQ(k.format(*k.find(name)), value) << name;
    // The seed's SSAO3 row is the built-in SSAO3's.
    KnobRegistry s3;
    Pipeline d3(s3);
    findBuiltinPreset("SSAO3")->applyOver(s3, {});
    for (const char* name : {"ssao.resolution", "ssao.samples", "ssao.radius", "ssao_blur.width"})
        EXPECT_EQ(k.format(*k.find(name)), s3.format(*s3.find(name))) << name;
    EXPECT_EQ(k.value(*k.find("bloom.threshold")), k.spec(*k.find("bloom.threshold")).defaultValue);
    EXPECT_NE(p->description.find("render size, not set by a preset: --size or the window"), std::string::npos);
}
