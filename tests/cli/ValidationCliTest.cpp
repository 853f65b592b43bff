// Each kind of invalid input from the issue tracker's cases, as a user runs
// it: `render` exits 1 with exactly one line on stderr that names the file
// and the field (or element) and says what is wrong; refused before any GL
// work. Valid extreme inputs next to them render with exit 0.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

namespace fs = std::filesystem;

namespace {

fs::path regression(const std::string& target, const std::string& name) {
    return fs::path(DW_FUZZ_DIR) / "regression" / target / name;
}

int lines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

// Runs render on `scene` (extra arguments after it) and checks the one-line refusal.
void expectRefused(const std::string& sceneArgs, const std::string& fileName, const std::string& field,
                   const std::string& what) {
    const auto r = dw::test::runWorkbench("render --size 160x90 " + sceneArgs + " --out " +
                                          (dw::test::tempDir() / "refused.png").string());
    EXPECT_EQ(r.code, 1) << sceneArgs;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    const std::string prefix = fileName + ": " + field + ": ";
    EXPECT_NE(r.err.find(prefix + what), std::string::npos) << "expected '" << prefix << what << "' in: " << r.err;
    EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
}

fs::path writeText(const std::string& name, const std::string& text) {
    const fs::path p = dw::test::tempDir() / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

}  // namespace

TEST(ValidationCli, NumberBeyondFloatIsOneLineNamingFileAndField) {
    expectRefused("--scene " + regression("scene_json", "light_intensity_beyond_float.json").string(),
                  "light_intensity_beyond_float.json", "lights[0].intensity[0]", "1e+39 does not fit a 32-bit float");
    expectRefused("--scene " + regression("scene_json", "number_beyond_double.json").string(), "number_beyond_double.json",
                  "camera.pos[1]", "1e400 is too large");
    expectRefused("--preset " + regression("preset", "camera_near_beyond_float.json").string(),
                  "camera_near_beyond_float.json", "camera.near", "1e39 does not fit a 32-bit float");
    const auto set = dw::test::runWorkbench("render --size 160x90 --set tonemap.key=1e39 --out " +
                                            (dw::test::tempDir() / "set.png").string());
    EXPECT_EQ(set.code, 1);
    EXPECT_NE(set.err.find("tonemap.key"), std::string::npos) << set.err;
}

TEST(ValidationCli, DegenerateCameraIsOneLineNamingTheField) {
    expectRefused("--scene " + regression("scene_json", "camera_up_parallel_to_view.json").string(),
                  "camera_up_parallel_to_view.json", "camera.up", "is parallel to the view direction");
}

TEST(ValidationCli, GltfValuesFollowTheSceneJsonRules) {
    expectRefused("--scene " + regression("gltf", "spot_outer_cone_over_90_degrees.gltf").string(),
                  "spot_outer_cone_over_90_degrees.gltf", "extensions.KHR_lights_punctual.lights[0].spot.outerConeAngle",
                  "must be in (0, pi/2] radians, got 3");
}

TEST(ValidationCli, ImageBytesPastTheBufferNameTheImageAndTheRange) {
    expectRefused("--scene " + regression("gltf", "image_bytes_past_buffer.glb").string(), "image_bytes_past_buffer.glb",
                  "image[0]", "bufferView[3] (bytes 840 to 3273) runs past the end of buffer[0] (900 bytes)");
}

TEST(ValidationCli, GlbHeaderDisagreeingWithTheFileSaysHow) {
    expectRefused("--scene " + regression("gltf", "chunk_too_big.glb").string(), "chunk_too_big.glb", "malformed GLB",
                  "the header declares a total length of 13 bytes but the file has 48");
}

// Issue 25: a required property tinygltf refuses without a reason, and every
// bad object of a kind, on one line naming the file and the objects.
TEST(ValidationCli, GltfSchemaBreaksAreOneLineNamingEachObject) {
    const std::string gltf = R"({"asset": {"version": "2.0"}, "skins": [{"name": "rig"}], "cameras": [
        {"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}},
        {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
        {"type": "perspective", "perspective": {"yfov": 0.8, "znear": -1}}],
        "bufferViews": [{"buffer": 0, "byteLength": 1e39}]})";
    expectRefused("--scene " + writeText("schema.gltf", gltf).string(), "schema.gltf", "bufferViews[0].byteLength",
                  "1e39 is out of range (a byte length from 1 to 9007199254740991)");
    const std::string rest = R"({"asset": {"version": "2.0"}, "skins": [{"name": "rig"}], "cameras": [
        {"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}},
        {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
        {"type": "perspective", "perspective": {"yfov": 0.8, "znear": -1}}]})";
    expectRefused("--scene " + writeText("objects.gltf", rest).string(), "objects.gltf", "cameras[0].perspective.yfov",
                  "must be in (0, 179) degrees, got 0 rad (0 degrees); cameras[2].perspective.znear: must be greater than 0, "
                  "got -1; skins[0]: required property 'joints' is missing");
}

// Issue 25: invalid but drawable: rendered (exit 0), with a warning that
// calls the file invalid and names the rule and the object.
TEST(ValidationCli, InvalidButDrawableGltfRendersWithAWarningNamingTheRule) {
    const fs::path scene = writeText("skin-no-mesh.gltf", R"({"asset": {"version": "2.0"},
        "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "skins": [{"joints": [0]}],
        "nodes": [{"mesh": 0}, {"skin": 0}], "scenes": [{"nodes": [0, 1]}], "scene": 0})");
    const fs::path out = dw::test::tempDir() / "skin-no-mesh.png";
    const auto r = dw::test::runWorkbench("render --size 160x90 --scene " + scene.string() + " --out " + out.string());
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(out));
    EXPECT_NE(r.err.find("warning: " + scene.string() +
                         ": invalid glTF (drawn anyway): nodes[1]: has skin 0 but no mesh (spec: a node with a skin has a mesh)"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("ignored (not supported by the workbench): 1 skin(s)"), std::string::npos) << r.err;
}

TEST(ValidationCli, DeepNestingIsOneLineInEveryReader) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    for (const auto& [args, name] : std::initializer_list<std::pair<std::string, std::string>>{
             {"--scene " + writeText("deep-scene.json", R"({"objects": )" + deep + "}").string(), "deep-scene.json"},
             {"--preset " + writeText("deep-preset.json", R"({"knobs": {"tonemap.key": )" + deep + "}}").string(), "deep-preset.json"},
             {"--scene " + writeText("deep-extras.gltf", R"({"asset": {"version": "2.0", "extras": )" + deep + "}}").string(),
              "deep-extras.gltf"}}) {
        const auto r = dw::test::runWorkbench("render --size 160x90 " + args + " --out " + (dw::test::tempDir() / "deep.png").string());
        EXPECT_EQ(r.code, 1) << name;
        EXPECT_EQ(lines(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(name + ": line 1, column "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("JSON nested deeper than 128 levels"), std::string::npos) << r.err;
    }
}

TEST(ValidationCli, LookingStraightDownWithoutAnUpRendersAFiniteFrame) {
    const fs::path scene = writeText("down.json", R"({"objects": [{"shape": "plane", "size": [10, 0, 10]}],
        "lights": [{"type": "point", "pos": [0, 3, 0], "intensity": [2, 2, 2]}],
        "camera": {"pos": [0, 9, 0], "look-at": [0, 0, 0]}})");
    const fs::path out = dw::test::tempDir() / "down.exr";
    const auto r = dw::test::runWorkbench("render --size 160x90 --buffer lbuffer --scene " + scene.string() + " --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    const dw::FloatImage img = dw::loadImageFloat(out.string());
    ASSERT_EQ(img.width, 160);
    double sum = 0.0;
    for (float v : img.pixels) {
        ASSERT_TRUE(std::isfinite(v));
        sum += v;
    }
    EXPECT_GT(sum / static_cast<double>(img.pixels.size()), 0.01);  // the floor is lit and in view
}
