#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "renderer/Error.h"
#include "renderer/scene/BuiltinScenes.h"
#include "renderer/scene/SceneJsonLoader.h"
#include "renderer/scene/SceneLoader.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

std::string errorOf(const std::string& json, const std::string& name = "scene.json") {
    try {
        parseSceneJson(json, (test::tempDir() / name).string());
    } catch (const FileError& e) {
        return e.what();
    }
    return "no error";
}

const char* kValid = R"({
  "name": "test",
  "camera": {"pos": [0, 2, 8], "look-at": [0, 0, 0], "fov": 45, "near": 0.5, "far": 50},
  "ambient": [0.1, 0.1, 0.1],
  "lights": [
    {"name": "lamp", "pos": [1, 4, 0], "direction": [0, -1, 0], "cutoff": 30, "exponent": 8,
     "intensity": [2, 2, 1.5], "attenuation": {"constant": 1, "linear": 0.1, "quadratic": 0.3}},
    {"name": "bulb", "type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1]},
    {"name": "sun", "type": "directional", "direction": [0, -2, 0], "intensity": [0.5, 0.5, 0.5]}
  ],
  "materials": {"red": {"diffuse": [0.8, 0.1, 0.1], "specular": [0.5, 0.5, 0.5], "shininess": 64}},
  "objects": [
    {"shape": "plane", "size": [10, 0, 10]},
    {"shape": "box", "size": [1, 2, 1], "pos": [2, 1, 0], "rotate": [0, 45, 0], "material": "red"},
    {"shape": "sphere", "radius": 0.5, "material": {"diffuse": [0.2, 0.8, 0.2]}}
  ]
})";

}  // namespace

TEST(SceneJson, ReadsCameraLightsMaterialsAndObjects) {
    const Scene s = parseSceneJson(kValid, "valid.json");
    EXPECT_EQ(s.name, "test");
    EXPECT_FLOAT_EQ(s.camera.fovYDegrees, 45.0f);
    EXPECT_FLOAT_EQ(s.camera.nearPlane, 0.5f);
    ASSERT_EQ(s.lights.size(), 3u);
    const Light& lamp = s.lights[0];
    EXPECT_EQ(lamp.type, LightType::Spot);  // inferred from "cutoff"
    EXPECT_FLOAT_EQ(lamp.cutoffDegrees, 30.0f);
    EXPECT_FLOAT_EQ(lamp.exponent, 8.0f);
    EXPECT_FLOAT_EQ(lamp.attenuation.quadratic, 0.3f);
    EXPECT_FLOAT_EQ(lamp.attenuation.linear, 0.1f);
    EXPECT_EQ(s.lights[1].type, LightType::Point);
    EXPECT_EQ(s.lights[2].type, LightType::Directional);
    EXPECT_NEAR(glm::length(s.lights[2].direction), 1.0f, 1e-6f);
    EXPECT_EQ(s.instances.size(), 3u);
    EXPECT_EQ(s.materials[s.meshes[1].material].name, "red");
    EXPECT_FLOAT_EQ(s.materials[s.meshes[1].material].specularExponent, 64.0f);
    EXPECT_TRUE(s.warnings.empty());
}

TEST(SceneJson, AcceptsTheAssignmentLightingBlock) {
    const Scene s = parseSceneJson(R"({"lighting": {"ambient": [0.2, 0.2, 0.2], "direction": [0, -1, 0],
        "intensity": [1, 1, 1], "lights": [{"name": "s", "pos": [0, 3, 0], "direction": [0, -1, 0], "cutoff": 20,
        "exponent": 2, "intensity": [1, 1, 1], "attenuation": {"constant": 1, "linear": 0, "quadratic": 0.3}}]},
        "objects": [{"shape": "box"}]})",
                                   "cmsc.json");
    EXPECT_FLOAT_EQ(s.ambient.x, 0.2f);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_EQ(s.lights[1].type, LightType::Spot);
}

TEST(SceneJson, MalformedJsonNamesFileLineAndColumn) {
    const std::string e = errorOf("{\n  \"name\": \"x\",\n  \"objects\": [ {,] \n}", "broken.json");
    EXPECT_NE(e.find("broken.json"), std::string::npos) << e;
    EXPECT_NE(e.find("line 3"), std::string::npos) << e;
    EXPECT_NE(e.find("malformed JSON"), std::string::npos) << e;
}

TEST(SceneJson, ANumberThatBecomes0AsAFloatIsNamedNotReadAs0) {
    const std::string e = errorOf(R"({"objects": [{"shape": "box", "size": [1e-50, 1, 1]}]})", "tiny.json");
    EXPECT_NE(e.find("tiny.json: objects[0].size[0]: 1e-50 is too small for a 32-bit float"), std::string::npos) << e;
    EXPECT_EQ(errorOf(R"({"objects": [{"shape": "box", "size": [1e-40, 1, 1]}]})"), "no error") << "a denormal float is a size";
}

// Found by a new user: 1.5 drew opaque and -0.1 invisible but counted, silently.
TEST(SceneJson, OpacityOutsideZeroToOneIsNamed) {
    for (const char* v : {"1.5", "-0.1"}) {
        const std::string e = errorOf(std::string(R"({"materials": {"glass": {"opacity": )") + v + "}}}", "op.json");
        EXPECT_NE(e.find("op.json: materials.glass.opacity: must be between 0 (invisible) and 1 (opaque)"), std::string::npos)
            << e;
    }
    EXPECT_EQ(errorOf(R"({"materials": {"glass": {"opacity": 0}}})"), "no error");
}

TEST(SceneJson, WrongTypesNameTheJsonPath) {
    EXPECT_NE(errorOf(R"({"lights": [{"pos": [0,1,0], "attenuation": {"quadratic": "high"}}]})")
                  .find("lights[0].attenuation.quadratic: expected a number, got string"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"camera": {"pos": [1, 2]}})").find("camera.pos: expected an array of 3 numbers"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"objects": [{"shape": "teapot"}]})").find("objects[0].shape: unknown shape"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"objects": [{"shape": "box", "material": "gold"}]})").find("no material named \"gold\""),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"lights": [{"type": "spot", "pos": [0,1,0], "direction": [0,-1,0], "cutoff": 120}]})")
                  .find("lights[0].cutoff: must be in (0, 90]"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"lights": [{"pos": [0,1,0], "attenuation": {"constant": 0, "linear": 0, "quadratic": 0}}]})")
                  .find("all 0"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"lights": [{"type": "spot", "pos": [0,1,0], "direction": [0,0,0]}]})")
                  .find("direction must not be zero"),
              std::string::npos);
    EXPECT_NE(errorOf(R"([1, 2, 3])").find("expected an object"), std::string::npos);
}

TEST(SceneJson, MissingTextureAndGltfNameTheFile) {
    const std::string tex = errorOf(R"({"materials": {"m": {"diffuse-map": "nope/brick.png"}}})", "tex.json");
    EXPECT_NE(tex.find("tex.json"), std::string::npos) << tex;
    EXPECT_NE(tex.find("missing texture 'nope/brick.png'"), std::string::npos) << tex;
    const std::string gltf = errorOf(R"({"objects": [{"gltf": "models/none.glb"}]})");
    EXPECT_NE(gltf.find("glTF file 'models/none.glb' not found"), std::string::npos) << gltf;
}

TEST(SceneJson, UnknownKeysWarnAndSettingsAreKept) {
    const Scene s = parseSceneJson(R"({"objects": [{"shape": "box", "colour": [1,0,0]}],
                                       "settings": {"tonemap.key": 0.1, "tonemap.operator": "simple", "lighting.frustum_cull": false}})",
                                   "w.json");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("objects[0].colour: unknown key"), std::string::npos);
    ASSERT_EQ(s.settings.size(), 3u);
    EXPECT_EQ(s.settings[1].second, "simple");
    EXPECT_EQ(s.settings[2].second, "false");
}

TEST(SceneJson, MissingFileAndUnknownSpec) {
    EXPECT_THROW(loadSceneJson("/nonexistent/scene.json"), FileError);
    try {
        loadScene("no-such-scene");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("built-in scene (default, street, spheres, glass, fire, atrium)"), std::string::npos);
    }
}

TEST(SceneJson, ProjectExampleScenesLoad) {
    int n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::scenesDir())) {
        if (entry.path().extension() != ".json") continue;
        const Scene s = loadSceneJson(entry.path().string());
        EXPECT_FALSE(s.instances.empty()) << entry.path();
        EXPECT_TRUE(s.warnings.empty()) << entry.path() << ": " << (s.warnings.empty() ? "" : s.warnings[0]);
        ++n;
    }
    EXPECT_GE(n, 1);
}

TEST(BuiltinScenes, HaveWhatTheIssueAsksFor) {
    const Scene d = makeBuiltinScene("default");
    EXPECT_GE(d.countLights(LightType::Point) + d.countLights(LightType::Spot), 24);  // dozens of coloured lights
    EXPECT_GE(d.countLights(LightType::Spot), 4);
    EXPECT_GE(d.countLights(LightType::Directional), 1);
    const Scene street = makeBuiltinScene("street");
    EXPECT_GE(street.countLights(LightType::Spot), 16);  // a long row of street lamps
    const Scene spheres = makeBuiltinScene("spheres");
    EXPECT_GE(spheres.materials.size(), 20u);
    for (const auto& info : builtinScenes()) {
        const Scene s = makeBuiltinScene(info.name);
        EXPECT_GT(s.triangleCount(), 100u) << info.name;
        for (const auto& m : s.meshes) {
            ASSERT_EQ(m.indices.size() % 3, 0u);
            for (uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size());
            for (const auto& v : m.vertices) {
                ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-3f) << info.name << " " << m.name;
                ASSERT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-3f) << info.name << " " << m.name;
            }
        }
    }
}

TEST(SceneJson, OneClipPlaneFitsTheOtherAndOnlyTwoCanConflict) {
    const std::string objects = R"("objects": [{"shape": "box", "size": [40, 1, 40]}])";
    const std::string path = (test::tempDir() / "clip.json").string();
    // Only far: a near plane below it, whatever the scene's size.
    const Scene farOnly = parseSceneJson(R"({"camera": {"pos": [0, 5, 30], "far": 0.5}, )" + objects + "}", path);
    EXPECT_FLOAT_EQ(farOnly.camera.farPlane, 0.5f);
    EXPECT_GT(farOnly.camera.nearPlane, 0.0f);
    EXPECT_LT(farOnly.camera.nearPlane, 0.5f);
    // Only near: a far plane beyond it.
    const Scene nearOnly = parseSceneJson(R"({"camera": {"pos": [0, 5, 30], "near": 500}, )" + objects + "}", path);
    EXPECT_FLOAT_EQ(nearOnly.camera.nearPlane, 500.0f);
    EXPECT_GT(nearOnly.camera.farPlane, 500.0f);
    // Neither: the fitted planes leave room to orbit out to twice the distance.
    const Scene fitted = parseSceneJson(R"({"camera": {"pos": [0, 5, 30]}, )" + objects + "}", path);
    const float r = fitted.bounds().radius();
    const float d = glm::length(fitted.bounds().center() - fitted.camera.position);
    EXPECT_GE(fitted.camera.farPlane, 2.0f * d + r);
    EXPECT_LE(fitted.camera.nearPlane, 0.01f * d);  // and to move in close
    // Both, out of order: the error names them.
    EXPECT_NE(errorOf(R"({"camera": {"pos": [0, 5, 30], "near": 5, "far": 1}})").find("camera.far: must be greater than camera.near"),
              std::string::npos);
}

// Issue 36: the atrium is seed 000 section 6.5's scene: several hundred
// objects, hundreds of thousands of triangles, transparent objects among
// them, and one light, a shadow-casting sun (bench adds the point lights).
TEST(BuiltinScenes, AtriumIsTheSeedsLargeSceneWithOneShadowedSun) {
    const Scene s = makeBuiltinScene("atrium");
    EXPECT_GE(s.instances.size(), 300u);
    EXPECT_LE(s.instances.size(), 500u);
    EXPECT_GE(s.triangleCount(), 250000u);
    EXPECT_TRUE(s.hasMaterial(AlphaMode::Blend));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_TRUE(s.lights[0].castShadows);
}
