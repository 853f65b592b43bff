// Invalid values in every reader (scene JSON, presets, glTF, knob values) are
// refused with a message that names the file and the field; degenerate
// cameras are refused or take their documented fallback; JSON depth is
// bounded. Each test asserts the message's words and, for what is accepted,
// the values that result (finite matrices, grey channels copied).
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>
#include <optional>
#include <random>
#include <typeinfo>
#include <filesystem>
#include <fstream>
#include <regex>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/Error.h"
#include "renderer/io/ImageIO.h"
#include "renderer/io/ImageLimits.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/knobs/Preset.h"
#include "renderer/scene/CameraCheck.h"
#include "renderer/scene/GltfLoader.h"
#include "renderer/scene/SceneJsonLoader.h"
#include "renderer/scene/SceneLoader.h"

using namespace dw;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path& dir() {
    static const fs::path d = [] {
        fs::path p = fs::temp_directory_path() / ("dw-reader-tests-" + std::to_string(::getpid()));
        fs::create_directories(p);
        return p;
    }();
    return d;
}

fs::path writeText(const std::string& name, const std::string& text) {
    const fs::path p = dir() / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

fs::path regression(const std::string& target, const std::string& name) {
    return fs::path(DW_FUZZ_DIR) / "regression" / target / name;
}

// The message loadScene gives for `path`, or "no error".
std::string sceneError(const fs::path& path) {
    try {
        loadScene(path.string());
    } catch (const FileError& e) {
        return e.what();
    }
    return "no error";
}

std::string presetError(const std::string& text, const std::string& name = "p.json") {
    try {
        Preset::fromJson(text, name);
    } catch (const FileError& e) {
        return e.what();
    }
    return "no error";
}

// A one-triangle glTF (embedded buffer) to break one field at a time.
json triangleGltf() {
    json j;
    j["asset"] = {{"version", "2.0"}};
    j["buffers"] = json::array({{{"byteLength", 44},
                                 {"uri", "data:application/octet-stream;base64,"
                                         "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}}});
    j["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                    {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}});
    j["accessors"] = json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                                   {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                                  {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}});
    j["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}})}}});
    j["nodes"] = json::array({{{"mesh", 0}}});
    j["scenes"] = json::array({{{"nodes", {0}}}});
    j["scene"] = 0;
    return j;
}

json withCamera(json j, const json& perspective, const json& node = {{"translation", {0, 0, 5}}}) {
    j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", perspective}}});
    json n = node;
    n["camera"] = 0;
    j["nodes"].push_back(n);
    j["scenes"][0]["nodes"].push_back(1);
    return j;
}

json withLight(json j, const json& light) {
    j["extensionsUsed"] = {"KHR_lights_punctual"};
    j["extensions"]["KHR_lights_punctual"]["lights"] = json::array({light});
    j["nodes"].push_back({{"translation", {0, 3, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    j["scenes"][0]["nodes"].push_back(1);
    return j;
}

std::string gltfError(const std::string& name, const json& j) { return sceneError(writeText(name, j.dump())); }

// A GLB of `chunks` (length field, type, data); the header's length is the
// file's size unless `declared` is given.
std::string glbOf(const std::vector<std::tuple<std::uint32_t, std::string, std::string>>& chunks, long declared = -1) {
    auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    std::string body;
    for (const auto& [length, type, data] : chunks) body += u32(length) + type + data;
    const auto total = static_cast<std::uint32_t>(declared >= 0 ? declared : static_cast<long>(12 + body.size()));
    return "glTF" + u32(2) + u32(total) + body;
}

const char* kSceneHead = R"({"objects": [{"shape": "box", "size": [1, 1, 1]}], )";
std::string scene(const std::string& rest) { return std::string(kSceneHead) + rest + "}"; }

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

}  // namespace

// ---- numbers beyond a float, everywhere -----------------------------------

TEST(ReaderValidation, SceneNumberBeyondFloatNamesFileAndField) {
    const std::string e = sceneError(regression("scene_json", "light_intensity_beyond_float.json"));
    EXPECT_HAS(e, "light_intensity_beyond_float.json: lights[0].intensity[0]: 1e+39 does not fit a 32-bit float");
    // Camera planes and positions, spot exponents: the same rule, the same words.
    EXPECT_HAS(sceneError(writeText("near.json", scene(R"("camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0], "near": 1e39})"))),
               "near.json: camera.near: 1e39 does not fit a 32-bit float");
    EXPECT_HAS(sceneError(writeText("pos.json", scene(R"("camera": {"pos": [0, -4e38, 5], "look-at": [0, 0, 0]})"))),
               "pos.json: camera.pos[1]: -4e38 does not fit a 32-bit float");
    EXPECT_HAS(sceneError(writeText("exp.json", scene(R"("lights": [{"pos": [0, 2, 0], "direction": [0, -1, 0], "exponent": 3.5e38}])"))),
               "exp.json: lights[0].exponent: 3.5e38 does not fit a 32-bit float");
}

TEST(ReaderValidation, NumberBeyondDoubleNamesThePathNotTheJsonLibrary) {
    const std::string e = sceneError(regression("scene_json", "number_beyond_double.json"));
    EXPECT_HAS(e, "number_beyond_double.json: camera.pos[1]: 1e400 is too large");
    EXPECT_EQ(e.find("json.exception"), std::string::npos) << e;
}

TEST(ReaderValidation, PresetNumbersBeyondFloatAreRefused) {
    std::ifstream in(regression("preset", "camera_near_beyond_float.json"));
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_HAS(presetError(text, "cam.json"), "cam.json: camera.near: 1e39 does not fit a 32-bit float");
    EXPECT_HAS(presetError(R"({"knobs": {"tonemap.key": 1e39}})"), "p.json: knobs.tonemap.key: 1e39 does not fit a 32-bit float");
    // A string where a number belongs is named, not the JSON library's type error.
    const std::string typed = presetError(R"({"knobs": {}, "camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0], "fov": "wide"}})");
    EXPECT_HAS(typed, "p.json: camera.fov: expected a number");
    EXPECT_HAS(presetError(R"({"name": 3, "knobs": {}})"), "p.json: name: expected a string");
}

TEST(ReaderValidation, KnobValueBeyondFloatIsRefused) {
    KnobRegistry k;
    k.addFloat("a.scale", 1.0, 0.0, 1e300, "a", "a float");
    try {
        k.applyAssignment("a.scale=1e39");
        ADD_FAILURE() << "1e39 accepted";
    } catch (const Error& e) {
        EXPECT_HAS(e.what(), "knob 'a.scale' = 1e39: 1e+39 does not fit a 32-bit float");
    }
    EXPECT_THROW(k.applyAssignment("a.scale=1e400"), Error);
    k.applyAssignment("a.scale=3e38");
    EXPECT_FLOAT_EQ(static_cast<float>(k.value(0)), 3e38f);
}

TEST(ReaderValidation, GltfCameraAndLightNumbersBeyondFloatAreRefused) {
    EXPECT_HAS(gltfError("zfar.gltf", withCamera(triangleGltf(), {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 1e39}})),
               "zfar.gltf: cameras[0].perspective.zfar: 1e+39 does not fit a 32-bit float");
    EXPECT_HAS(gltfError("intensity.gltf", withLight(triangleGltf(), {{"type", "point"}, {"intensity", 1e39}})),
               "intensity.gltf: extensions.KHR_lights_punctual.lights[0].intensity: 1e+39 does not fit a 32-bit float");
    // Any number of the file: a node translation.
    json j = triangleGltf();
    j["nodes"][0]["translation"] = {0, 5e38, 0};
    EXPECT_HAS(gltfError("node.gltf", j), "node.gltf: nodes[0].translation[1]: 5e+38 does not fit a 32-bit float");
}

// ---- cameras ---------------------------------------------------------------

TEST(ReaderValidation, UpParallelToViewOrZeroIsAnError) {
    EXPECT_HAS(sceneError(regression("scene_json", "camera_up_parallel_to_view.json")),
               "camera_up_parallel_to_view.json: camera.up: is parallel to the view direction");
    EXPECT_HAS(sceneError(writeText("zero-up.json", scene(R"("camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0], "up": [0, 0, 0]})"))),
               "zero-up.json: camera.up: must not be zero");
    EXPECT_HAS(presetError(R"({"knobs": {}, "camera": {"pos": [0, 9, 0], "look-at": [0, 0, 0], "up": [0, 1, 0]}})"),
               "p.json: camera.up: is parallel to the view direction");
}

TEST(ReaderValidation, WithoutAnUpALookStraightDownUsesMinusZ) {
    const Scene s = parseSceneJson(scene(R"("camera": {"pos": [0, 9, 0], "look-at": [0, 0, 0]})"), (dir() / "down.json").string());
    EXPECT_EQ(s.camera.up, glm::vec3(0, 0, -1));
    EXPECT_TRUE(finite(s.camera.view()));
    EXPECT_TRUE(finite(s.camera.projection(16.0f / 9.0f)));
}

TEST(ReaderValidation, ClipPlanesAndFieldOfViewOutsideTheirRangesAreErrors) {
    auto err = [](const std::string& name, const std::string& camera) {
        return sceneError(writeText(name, scene(R"("camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0], )" + camera + "}")));
    };
    EXPECT_HAS(err("denormal.json", R"("near": 1e-39, "far": 10)"), "denormal.json: camera.near: 1e-39 is below the smallest normal 32-bit float");
    EXPECT_HAS(err("zero-near.json", R"("near": 0)"), "zero-near.json: camera.near: must be greater than 0");
    EXPECT_HAS(err("order.json", R"("near": 5, "far": 5)"), "order.json: camera.far: must be greater than camera.near");
    EXPECT_HAS(err("fov0.json", R"("fov": 0)"), "fov0.json: camera.fov: must be greater than 0");
    EXPECT_HAS(err("fov180.json", R"("fov": 180)"), "fov180.json: camera.fov: must be less than 179 degrees");
    EXPECT_HAS(presetError(R"({"knobs": {}, "camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0], "near": 2, "far": 1}})"),
               "p.json: camera.far: must be greater than near (2), got 1");
    EXPECT_HAS(presetError(R"({"knobs": {}, "camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0], "fov": 180}})"),
               "p.json: camera.fov: must be in (0, 179) degrees, got 180");
}

TEST(ReaderValidation, LookAtDistanceIsRelativeToTheScene) {
    // A scene 1e-8 across, seen from 1e-8 away: accepted, finite matrices.
    const Scene tiny = parseSceneJson(
        R"({"objects": [{"shape": "box", "size": [1e-8, 1e-8, 1e-8]}],
            "camera": {"pos": [0, 0, 1e-8], "look-at": [0, 0, 0], "near": 1e-10, "far": 1e-7}})",
        (dir() / "tiny.json").string());
    EXPECT_TRUE(finite(tiny.camera.view()));
    EXPECT_TRUE(finite(tiny.camera.projection(1.0f)));
    // The same 1e-8 in a scene 100 units across, 50 units from the origin, is no view direction.
    EXPECT_HAS(sceneError(writeText("close.json", R"({"objects": [{"shape": "box", "size": [100, 100, 100]}],
            "camera": {"pos": [50, 0, 1e-8], "look-at": [50, 0, 0]}})")),
               "close.json: camera.look-at: must differ from pos");
    Camera c;
    c.position = {0, 0, 1e-8f};
    c.target = {0, 0, 0};
    c.nearPlane = 1e-10f;
    c.farPlane = 1e-7f;
    EXPECT_FALSE(findCameraProblem(c, 2e-8f));
    ASSERT_TRUE(findCameraProblem(c, 200.0f));
    EXPECT_EQ(findCameraProblem(c, 200.0f)->field, "look-at");
}

TEST(ReaderValidation, GltfCameraProblemsAreNamed) {
    EXPECT_HAS(gltfError("yfov0.gltf", withCamera(triangleGltf(), {{"yfov", 0}, {"znear", 0.1}})),
               "yfov0.gltf: cameras[0].perspective.yfov: must be in (0, 179) degrees, got 0");
    EXPECT_HAS(gltfError("znear.gltf", withCamera(triangleGltf(), {{"yfov", 0.8}, {"znear", 0}})),
               "znear.gltf: cameras[0].perspective.znear: must be greater than 0");
    EXPECT_HAS(gltfError("zfar.gltf", withCamera(triangleGltf(), {{"yfov", 0.8}, {"znear", 1}, {"zfar", 0.5}})),
               "zfar.gltf: cameras[0].perspective.zfar: must be greater than znear (1), got 0.5");
    EXPECT_HAS(gltfError("scale0.gltf", withCamera(triangleGltf(), {{"yfov", 0.8}, {"znear", 0.1}},
                                                   {{"translation", {0, 0, 5}}, {"scale", {0, 0, 0}}})),
               "scale0.gltf: camera[0]: its node's transform has zero scale");
    // A tiny (not zero) scale still gives a direction: no underflow on the way.
    Scene small = loadScene(writeText("small-scale.gltf", withCamera(triangleGltf(), {{"yfov", 0.8}, {"znear", 0.1}},
                                                                     {{"translation", {0, 0, 5}}, {"scale", {1e-25, 1e-25, 1e-25}}})
                                                              .dump())
                                .string());
    EXPECT_NEAR(glm::length(small.camera.target - small.camera.position), 1.0f, 1e-5f);
    EXPECT_NEAR(small.camera.up.y, 1.0f, 1e-5f);
    // An accepted camera gives finite matrices.
    Scene s = loadScene(writeText("ok-camera.gltf", withCamera(triangleGltf(), {{"yfov", 0.8}, {"znear", 0.1}}).dump()).string());
    EXPECT_NEAR(s.camera.fovYDegrees, glm::degrees(0.8f), 1e-3f);
    EXPECT_TRUE(finite(s.camera.view()));
    EXPECT_TRUE(finite(s.camera.projection(1.0f)));
}

// ---- the glTF importer accepts what the scene JSON loader accepts ------------

TEST(ReaderValidation, GltfLightsFollowTheSceneJsonRules) {
    EXPECT_HAS(gltfError("neg.gltf", withLight(triangleGltf(), {{"type", "point"}, {"intensity", -2}})),
               "neg.gltf: extensions.KHR_lights_punctual.lights[0].intensity: must not be negative, got -2");
    EXPECT_HAS(sceneError(writeText("neg.json", scene(R"("lights": [{"pos": [0, 2, 0], "intensity": [-2, 1, 1]}])"))),
               "neg.json: lights[0].intensity: must not be negative");
    EXPECT_HAS(sceneError(regression("gltf", "spot_outer_cone_over_90_degrees.gltf")),
               "spot_outer_cone_over_90_degrees.gltf: extensions.KHR_lights_punctual.lights[0].spot.outerConeAngle: "
               "must be in (0, pi/2] radians, got 3");
    EXPECT_HAS(gltfError("inner.gltf", withLight(triangleGltf(), {{"type", "spot"},
                                                                  {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.5}}}})),
               "inner.gltf: extensions.KHR_lights_punctual.lights[0].spot.innerConeAngle: must be at least 0 and less than outerConeAngle");
    // pi/2 as a 32-bit float writes it (1.5707963705) is the edge, not beyond it.
    Scene s = loadScene(writeText("edge.gltf", withLight(triangleGltf(), {{"type", "spot"},
                                                                         {"spot", {{"outerConeAngle", 1.5707963705062866}}}})
                                                   .dump())
                            .string());
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_FLOAT_EQ(s.lights[0].cutoffDegrees, 90.0f);
    EXPECT_TRUE(std::isfinite(s.lights[0].exponent));
}

// ---- messages in the user's terms --------------------------------------------

TEST(ReaderValidation, GlbHeaderProblemsAreNamedAsSuch) {
    const std::string glb = "glTF" + std::string("\x02\0\0\0", 4);
    auto err = [](const std::string& name, const std::string& bytes) { return sceneError(writeText(name, bytes)); };
    EXPECT_HAS(err("short.glb", "glTF"), "short.glb: malformed GLB: the file is 4 bytes, shorter than the 12-byte GLB header");
    EXPECT_HAS(err("magic.glb", "{\"asset\": {\"version\": \"2.0\"}}"), "magic.glb: malformed GLB: the file does not start with the GLB magic");
    EXPECT_HAS(err("v1.glb", "glTF" + std::string("\x01\0\0\0\x14\0\0\0", 8) + std::string(8, '\0')), "v1.glb: malformed GLB: GLB version 1");
    EXPECT_HAS(err("length.glb", glb + std::string("\xff\0\0\0", 4) + std::string(8, '\0')),
               "length.glb: malformed GLB: the header declares a total length of 255 bytes but the file has 20 (cut short?)");
    EXPECT_HAS(err("chunk.glb", glb + std::string("\x20\0\0\0\x40\0\0\0JSON", 12) + std::string(12, ' ')),
               "chunk.glb: malformed GLB: the JSON chunk declares 64 bytes but only 12 follow its header (the file has 32)");
}

// Each way a GLB's header and chunk headers can disagree with each other or
// with the file names itself (the declared total against the file's size, a
// chunk's length against what is left), not a neighbouring problem.
TEST(ReaderValidation, EveryGlbInconsistencyNamesItself) {
    const std::string text = R"({"asset":{"version":"2.0"}} )";  // 28 bytes
    const std::string bin(8, '\0');
    auto err = [](const std::string& name, const std::string& bytes) { return sceneError(writeText(name, bytes)); };
    // The issue's chunk_too_big.glb: the header says 13 bytes, the file has 48 with a whole JSON chunk.
    const std::string e = sceneError(regression("gltf", "chunk_too_big.glb"));
    EXPECT_HAS(e, "chunk_too_big.glb: malformed GLB: the header declares a total length of 13 bytes but the file has 48");
    EXPECT_EQ(e.find("ends after the header"), std::string::npos) << e;
    EXPECT_HAS(err("long.glb", glbOf({{28, "JSON", text}}, 100)),
               "long.glb: malformed GLB: the header declares a total length of 100 bytes but the file has 48 (cut short?)");
    EXPECT_HAS(err("header-only.glb", glbOf({})), "header-only.glb: malformed GLB: no JSON chunk: the file ends after the 12-byte header");
    EXPECT_HAS(err("half-chunk.glb", glbOf({}, 16) + std::string("\x1c\0\0\0", 4)),
               "half-chunk.glb: malformed GLB: the JSON chunk's header is incomplete: 4 byte(s) after the 12-byte file header, a chunk header takes 8");
    EXPECT_HAS(err("bin-first.glb", glbOf({{8, std::string("BIN\0", 4), bin}, {28, "JSON", text}})),
               "bin-first.glb: malformed GLB: the first chunk is of type 0x004E4942 (\"BIN\\0\"), not JSON (0x4E4F534A)");
    EXPECT_HAS(err("empty-text.glb", glbOf({{0, "JSON", ""}})), "empty-text.glb: malformed GLB: the JSON chunk is empty (chunkLength 0)");
    EXPECT_HAS(err("text-long.glb", glbOf({{40, "JSON", text}})),
               "text-long.glb: malformed GLB: the JSON chunk declares 40 bytes but only 28 follow its header (the file has 48)");
    EXPECT_HAS(err("bin-long.glb", glbOf({{28, "JSON", text}, {16, std::string("BIN\0", 4), bin}})),
               "bin-long.glb: malformed GLB: the binary chunk (at byte 48) declares 16 bytes but only 8 follow its header (the file has 64)");
    EXPECT_HAS(err("tail.glb", glbOf({{28, "JSON", text}}, 52) + std::string(4, '\0')),
               "tail.glb: malformed GLB: chunk 1 (at byte 48): 4 byte(s) left, too few for a chunk header (8 bytes)");
    EXPECT_HAS(err("xyz.glb", glbOf({{28, "JSON", text}, {8, "XYZW", bin}})),
               "xyz.glb: malformed GLB: chunk 1 (at byte 48) is of type 0x575A5958 (\"XYZW\"), not BIN (0x004E4942)");
    EXPECT_HAS(err("two-bin.glb", glbOf({{28, "JSON", text}, {8, std::string("BIN\0", 4), bin}, {8, std::string("BIN\0", 4), bin}})),
               "two-bin.glb: malformed GLB: chunk 2 (at byte 64) is a second binary chunk (a GLB has at most one)");
    EXPECT_HAS(err("two-text.glb", glbOf({{28, "JSON", text}, {8, std::string("BIN\0", 4), bin}, {28, "JSON", text}})),
               "two-text.glb: malformed GLB: chunk 2 (at byte 64) is a second JSON chunk (a GLB has exactly one)");
    EXPECT_HAS(err("empty-bin.glb", glbOf({{28, "JSON", text}, {0, std::string("BIN\0", 4), ""}})),
               "empty-bin.glb: malformed GLB: the binary chunk is empty (chunkLength 0");
    EXPECT_HAS(err("bin-6.glb", glbOf({{28, "JSON", text}, {6, std::string("BIN\0", 4), std::string(6, '\0')}})),
               "bin-6.glb: malformed GLB: the binary chunk's length (6 bytes) is not a multiple of 4");
}

// A JSON chunk whose length is not a multiple of 4 breaks the spec but reads:
// drawn, with the file called invalid.
TEST(ReaderValidation, UnalignedGlbJsonChunkIsReadAndCalledInvalid) {
    std::string text = triangleGltf().dump();
    if (text.size() % 4 == 0) text += ' ';
    const fs::path p = writeText("unaligned.glb", glbOf({{static_cast<std::uint32_t>(text.size()), "JSON", text}}));
    const Scene s = loadScene(p.string());
    EXPECT_EQ(s.triangleCount(), 1u);
    std::string all;
    for (const auto& w : s.warnings) all += w + "\n";
    EXPECT_HAS(all, "unaligned.glb: invalid glTF (drawn anyway): GLB: the JSON chunk's length (" + std::to_string(text.size()) +
                        " bytes) is not a multiple of 4 (spec: chunks end on a 4-byte boundary)");
}

// What tinygltf refuses without a reason, integers out of range and several
// bad objects at once: each named by file, object and rule (issue 25).
TEST(ReaderValidation, GltfSchemaBreaksAreNamedByObject) {
    json j = triangleGltf();
    j["skins"] = json::array({{{"name", "rig"}}});
    EXPECT_HAS(gltfError("nojoints.gltf", j), "nojoints.gltf: skins[0]: required property 'joints' is missing");
    j = triangleGltf();
    std::string text = j.dump();
    const std::string count = "\"count\":3";
    text.replace(text.find(count), count.size(), "\"count\":4e40");
    const std::string e = sceneError(writeText("count.gltf", text));
    EXPECT_HAS(e, "count.gltf: accessors[0].count: 4e40 is out of range (a count from 1 to 9007199254740991)");
    EXPECT_EQ(e.find("32-bit float"), std::string::npos) << e;
    j = withCamera(triangleGltf(), {{"yfov", 0}, {"znear", 0.1}});
    j["cameras"].push_back({{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}});
    j["cameras"].push_back({{"type", "perspective"}, {"perspective", {{"yfov", 0.8}}}});
    EXPECT_HAS(gltfError("cams.gltf", j), "cams.gltf: cameras[0].perspective.yfov: must be in (0, 179) degrees, got 0 rad "
                                          "(0 degrees); cameras[2].perspective: required property 'znear' is missing");
    // A buffer without a uri: only a GLB's buffer 0, with a binary chunk that holds it.
    j = triangleGltf();
    j["buffers"][0].erase("uri");
    EXPECT_HAS(gltfError("nouri.gltf", j), "nouri.gltf: buffers[0]: required property 'uri' is missing (only a GLB's buffer 0 may leave it out)");
    std::string text2 = j.dump();
    text2.resize((text2.size() + 3) & ~std::size_t(3), ' ');
    const auto n = static_cast<std::uint32_t>(text2.size());
    EXPECT_HAS(sceneError(writeText("nobin.glb", glbOf({{n, "JSON", text2}}))),
               "nobin.glb: buffers[0]: has no uri and the GLB has no binary chunk");
    EXPECT_HAS(sceneError(writeText("smallbin.glb", glbOf({{n, "JSON", text2}, {8, std::string("BIN\0", 4), std::string(8, '\0')}}))),
               "smallbin.glb: buffers[0].byteLength: 44 is more than the binary chunk's 8 bytes");
}

TEST(ReaderValidation, MalformedDataUriIsNotFileNotFound) {
    json j = triangleGltf();
    j["buffers"][0]["uri"] = "data:application/foo;base64,AAAA";
    const std::string type = gltfError("uri-type.gltf", j);
    EXPECT_HAS(type, "uri-type.gltf: buffers[0].uri: malformed data: URI: media type 'application/foo'");
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64,AA*A";
    EXPECT_HAS(gltfError("uri-char.gltf", j), "uri-char.gltf: buffers[0].uri: malformed data: URI: invalid base64 character");
    j["buffers"][0]["uri"] = "data:application/octet-stream,plain";
    EXPECT_HAS(gltfError("uri-plain.gltf", j), "buffers[0].uri: malformed data: URI: the data is not marked ;base64");
    EXPECT_EQ(type.find("not found"), std::string::npos) << type;
}

TEST(ReaderValidation, OneChannelEnvironmentImageIsReadAsGrey) {
    FloatImage grey;
    grey.width = 4;
    grey.height = 2;
    grey.channels = 1;
    for (int i = 0; i < 8; ++i) grey.pixels.push_back(0.25f * static_cast<float>(i));
    writeImage((dir() / "grey.exr").string(), grey, {"Y"});
    const Scene s = parseSceneJson(R"({"sky": {"type": "environment", "file": "grey.exr"}})", (dir() / "sky.json").string());
    ASSERT_EQ(s.sky.equirect.channels, 3);
    ASSERT_EQ(s.sky.equirect.pixels.size(), 24u);
    for (int i = 0; i < 8; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(s.sky.equirect.pixels[i * 3 + c], 0.25f * static_cast<float>(i));
    // A missing one is named once: the scene file, the field, the image.
    const std::string e = sceneError(writeText("nosky.json", R"({"sky": {"type": "environment", "file": "none.exr"}})"));
    EXPECT_HAS(e, "nosky.json: sky.file: environment image 'none.exr' not found");
    EXPECT_EQ(e.find("sky.file", e.find("sky.file") + 1), std::string::npos) << e;
}

// ---- memory safety -----------------------------------------------------------

TEST(ReaderValidation, ImageBytesPastTheirBufferAreRefusedBeforeAnyRead) {
    // Under AddressSanitizer (scripts/test.sh --sanitize, the CI sanitizer
    // test) a read outside the buffer would stop this test.
    const std::string e = sceneError(regression("gltf", "image_bytes_past_buffer.glb"));
    EXPECT_HAS(e, "image_bytes_past_buffer.glb: image[0]: bufferView[3] (bytes 840 to 3273) runs past the end of buffer[0] (900 bytes)");
}

TEST(ReaderValidation, DeepNestingIsRefusedInEveryReader) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    EXPECT_HAS(sceneError(writeText("deep.json", R"({"objects": )" + deep + "}")),
               "deep.json: line 1, column 140: JSON nested deeper than 128 levels (at objects[0][0]");
    EXPECT_HAS(presetError(R"({"knobs": {"tonemap.key": )" + deep + "}}"), "p.json: line 1, column 153: JSON nested deeper than 128 levels");
    EXPECT_HAS(sceneError(writeText("deep.gltf", R"({"asset": {"version": "2.0", "extras": )" + deep + "}}")),
               "deep.gltf: line 1, column 166: JSON nested deeper than 128 levels (at asset.extras[0]");
    // 128 levels are read; 129 are not.
    EXPECT_NO_THROW(checkJsonText(std::string(128, '[') + std::string(128, ']'), "ok.json"));
    EXPECT_THROW(checkJsonText(std::string(129, '[') + std::string(129, ']'), "deep.json"), FileError);
}

TEST(ReaderValidation, EveryJsonTheProductReadsGoesThroughTheGuard) {
    // One helper guards and parses (parseJson, readJsonFile): no reader of
    // the product may call the JSON library's parser past it (the window's
    // layout.json did, and 150 000 levels overflowed the stack at start-up).
    const std::regex direct(R"(json::parse\s*\(|json::accept\s*\(|json::sax_parse|>>\s*\w*json\b)", std::regex::icase);
    std::vector<std::string> offenders;
    for (const char* top : {"app", "renderer", "ui"})
        for (const auto& e : fs::recursive_directory_iterator(fs::path(DW_SOURCE_DIR) / top)) {
            const std::string ext = e.path().extension().string();
            if (ext != ".cpp" && ext != ".h") continue;
            if (e.path().filename() == "JsonGuard.cpp") continue;  // the helper itself
            std::ifstream in(e.path());
            std::string line;
            for (int n = 1; std::getline(in, line); ++n)
                if (std::regex_search(line, direct))
                    offenders.push_back(fs::relative(e.path(), DW_SOURCE_DIR).string() + ":" + std::to_string(n));
        }
    EXPECT_TRUE(offenders.empty()) << "JSON parsed without parseJson at " << ::testing::PrintToString(offenders);

    // The helper: depth first, then the parse, malformed JSON by position.
    const std::string deep = std::string(150000, '[') + std::string(150000, ']');
    const fs::path layout = writeText("layout.json", R"({"layout": )" + deep + "}");
    std::string e;
    try {
        readJsonFile(layout.string(), {kMaxJsonDepth, false});
    } catch (const FileError& x) {
        e = x.what();
    }
    EXPECT_HAS(e, "layout.json: line 1, column 139: JSON nested deeper than 128 levels (at layout[0]");
    try {
        parseJson("{\"a\": [1, 2,, 3]}", "bad.json");
        e = "no error";
    } catch (const FileError& x) {
        e = x.what();
    }
    EXPECT_HAS(e, "bad.json: malformed JSON at line 1, column 13: syntax error while parsing value");
    EXPECT_EQ(parseJson(R"({"a": [1, 2e300]})", "big.json", {kMaxJsonDepth, false})["a"][1].get<double>(), 2e300);
    EXPECT_THROW(parseJson(R"({"a": [1, 2e300]})", "big.json"), FileError);  // beyond a float by default
}

TEST(ReaderValidation, ImageLibrariesDoNotWriteTheirOwnLinesToStderr) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "sanitizer builds leave stderr alone (StderrCapture.h)";
#endif
    // A PNG whose IDAT chunk type is corrupt: libpng prints "libpng error: ..." itself.
    const std::string png =
        std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\0\x04\0\0\0\x04\x08\x06\0\0\0", 29) +
        std::string("\xa9\xf1\x9e\x7e\0\0\0\x0cIDXT", 12) + std::string(16, '\x01');
    writeText("corrupt.png", png);
    const fs::path sceneFile = writeText("corrupt-texture.json",
                                    R"({"materials": {"m": {"diffuse-map": "corrupt.png"}}, "objects": [{"shape": "box", "material": "m"}]})");
    testing::internal::CaptureStderr();
    const std::string e = sceneError(sceneFile);
    const std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_HAS(e, "corrupt-texture.json: materials.m.diffuse-map: cannot load texture: ");
    EXPECT_HAS(e, "corrupt.png");
    EXPECT_EQ(printed, "");
}

// ---- damaged images: the memory budget ---------------------------------------

namespace {

// A small valid OpenEXR file (OIIO writes it: 16 x 8, RGB float).
std::string smallExr() {
    FloatImage img;
    img.width = 16;
    img.height = 8;
    img.channels = 3;
    img.pixels.assign(16 * 8 * 3, 0.5f);
    const fs::path p = dir() / "small-valid.exr";
    writeImage(p.string(), img);
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct ExrAttribute {
    std::string name, type;
    std::size_t sizeAt = 0, valueAt = 0;  // byte offsets of the size field and the value
    std::int32_t size = 0;
};

std::int32_t le32(const std::string& b, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
    return static_cast<std::int32_t>(v);
}
void put32(std::string& b, std::size_t at, std::int32_t v) {
    for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<char>((static_cast<std::uint32_t>(v) >> (8 * i)) & 0xff);
}

// The single-part header's attributes, in file order; `end` gets the byte of its closing 0.
std::vector<ExrAttribute> exrAttributes(const std::string& b, std::size_t* end = nullptr) {
    std::vector<ExrAttribute> v;
    std::size_t i = 8;
    while (b[i] != '\0') {
        ExrAttribute a;
        a.name = b.substr(i, b.find('\0', i) - i);
        i += a.name.size() + 1;
        a.type = b.substr(i, b.find('\0', i) - i);
        i += a.type.size() + 1;
        a.sizeAt = i;
        a.size = le32(b, i);
        a.valueAt = i + 4;
        i = a.valueAt + static_cast<std::size_t>(a.size);
        v.push_back(a);
    }
    if (end) *end = i;
    return v;
}

const ExrAttribute& attribute(const std::vector<ExrAttribute>& v, const std::string& name) {
    for (const auto& a : v)
        if (a.name == name) return a;
    throw std::runtime_error("no attribute " + name);
}

std::string withBox(std::string b, const std::string& name, std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1) {
    const std::size_t at = attribute(exrAttributes(b), name).valueAt;
    put32(b, at, x0);
    put32(b, at + 4, y0);
    put32(b, at + 8, x1);
    put32(b, at + 12, y1);
    return b;
}

// What loadImageFloat (or loadImage8) says of these bytes, "no error", or
// the type of any exception that is not a FileError.
std::string imageError(const std::string& name, const std::string& bytes, bool eightBit = false) {
    const fs::path p = writeText(name, bytes);
    try {
        if (eightBit) loadImage8(p.string());
        else loadImageFloat(p.string());
    } catch (const FileError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("not a FileError: ") + typeid(e).name() + ": " + e.what();
    }
    return "no error";
}

struct ScopedEnv {
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value) ::setenv(name, value, 1);
        else ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_) ::setenv(name_, old_->c_str(), 1);
        else ::unsetenv(name_);
    }
    const char* name_;
    std::optional<std::string> old_;
};

}  // namespace

TEST(ReaderValidation, DamagedExrHeadersAreRefusedByNameBeforeDecoding) {
    const ScopedEnv noLimit(kImageLimitVariable, nullptr);
    const std::string exr = smallExr();
    ASSERT_EQ(imageError("ok.exr", exr), "no error");
    const auto start = std::chrono::steady_clock::now();
    // A data window within OpenEXR's coordinates but over the budget: 30000 x
    // 30000 x 3 channels x 4 bytes as floats; as 8 bits, a quarter.
    const std::string big = withBox(exr, "dataWindow", 0, 0, 29999, 29999);
    const std::string budget = "big.exr: the OpenEXR data window (0, 0) to (29999, 29999) is 30000 x 30000 pixels of 3 channels: ";
    EXPECT_HAS(imageError("big.exr", big), budget + "10299.7 MB decoded, over the image memory limit of 1024 MB (set DW_IMAGE_LIMIT_MB=MB to raise it)");
    EXPECT_HAS(imageError("big.exr", big, true), budget + "2574.9 MB decoded, over the image memory limit of 1024 MB");
    // Embedded in a glTF (bytes, not a file): the image's name.
    const auto* b = reinterpret_cast<const std::uint8_t*>(big.data());
    EXPECT_THROW(
        try { decodeImage8(b, big.size(), "model.glb: image[0]", "image/png"); } catch (const FileError& e) {
            EXPECT_HAS(e.what(), "model.glb: image[0]: the OpenEXR data window (0, 0) to (29999, 29999)");
            throw;
        },
        FileError);
    // Coordinates beyond OpenEXR's range, data and display windows; inverted windows.
    EXPECT_HAS(imageError("far.exr", withBox(exr, "dataWindow", 0, 0, 2000000000, 2000000000)),
               "far.exr: the OpenEXR data window (0, 0) to (2000000000, 2000000000) has coordinates beyond +-1073741823 (a damaged header)");
    EXPECT_HAS(imageError("display.exr", withBox(exr, "displayWindow", INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX)),
               "display.exr: the OpenEXR display window (-2147483648, -2147483648) to (2147483647, 2147483647) has coordinates beyond");
    EXPECT_HAS(imageError("inverted.exr", withBox(exr, "dataWindow", 10, 0, 0, 7)),
               "inverted.exr: the OpenEXR data window (10, 0) to (0, 7) is empty (its maximum is below its minimum)");
    // A header cut short, inside an attribute and before its end.
    std::size_t end = 0;
    const auto attrs = exrAttributes(exr, &end);
    EXPECT_HAS(imageError("cut.exr", exr.substr(0, attribute(attrs, "dataWindow").valueAt + 6)),
               "cut.exr: the OpenEXR header is cut short: attribute 'dataWindow' runs past the end of the file");
    EXPECT_HAS(imageError("cut2.exr", exr.substr(0, end)), "cut2.exr: the OpenEXR header is cut short: an attribute name runs past the end");
    // An attribute claiming 2 GB (OpenEXR allocated it: 16 s and 2.2 GB before "Unexpected end of file").
    std::string huge = exr;
    put32(huge, attrs.front().sizeAt, 0x7ffffff0);
    EXPECT_HAS(imageError("attr.exr", huge), "attr.exr: the OpenEXR header is cut short: attribute '" + attrs.front().name +
                                                 "' runs past the end of the file (" + std::to_string(exr.size()) + " bytes)");
    std::string negative = exr;
    put32(negative, attrs.front().sizeAt, -5);
    EXPECT_HAS(imageError("negative.exr", negative), "negative.exr: the OpenEXR header is damaged: attribute '" + attrs.front().name +
                                                         "' has a negative size (-5)");
    // A channel of an unknown pixel type; no channels at all.
    std::string type = exr;
    const ExrAttribute& ch = attribute(attrs, "channels");
    put32(type, ch.valueAt + 2, 7);  // the first channel's name is one letter
    EXPECT_HAS(imageError("type.exr", type), "type.exr: the OpenEXR header is damaged: channel '" + exr.substr(ch.valueAt, 1) +
                                                 "' has pixel type 7 (0 to 2 exist)");
    // Every attempt is quick: nothing was allocated from the header.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(ReaderValidation, TheImageMemoryLimitIsRaisedByItsVariable) {
    const std::string exr = smallExr();
    const std::string big = withBox(exr, "dataWindow", 0, 0, 29999, 29999);
    {
        // Raised: the header passes, and the decoder finds the file cut short
        // (13 KB of pixels for 30000 rows) without allocating 10 GB first.
        const ScopedEnv raised(kImageLimitVariable, "20000");
        const std::string e = imageError("big-raised.exr", big);
        EXPECT_HAS(e, "big-raised.exr: ");
        EXPECT_EQ(e.find("image memory limit"), std::string::npos) << e;
        EXPECT_EQ(e.find("not a FileError"), std::string::npos) << e;
    }
    {
        // Lowered below the small file: refused with the limit it was given.
        const ScopedEnv lowered(kImageLimitVariable, "1");
        EXPECT_EQ(imageError("ok.exr", exr), "no error");  // 16 x 8 x 3 x 4 bytes
        FloatImage img;
        img.width = 512;
        img.height = 512;
        img.channels = 3;
        img.pixels.assign(512 * 512 * 3, 1.0f);
        writeImage((dir() / "big.png").string(), img);
        EXPECT_HAS(imageError("big.png", [] {
                       std::ifstream in(dir() / "big.png", std::ios::binary);
                       return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
                   }()),
                   "big.png: the image is 512 x 512 pixels of 3 channels: 3.0 MB decoded, over the image memory limit of 1 MB");
    }
    for (const char* bad : {"0", "-3", "lots", "12MB", ""}) {
        const ScopedEnv wrong(kImageLimitVariable, bad);
        if (!*bad) {
            EXPECT_EQ(imageMemoryLimit(), kDefaultImageLimitMB * 1024 * 1024);
            continue;
        }
        try {
            imageMemoryLimit();
            ADD_FAILURE() << bad;
        } catch (const Error& e) {
            EXPECT_HAS(e.what(), std::string("DW_IMAGE_LIMIT_MB is '") + bad + "': it takes a whole number of megabytes");
        }
    }
}

TEST(ReaderValidation, CorruptExrBytesAreAFileErrorOrAnImageNeverAnotherException) {
    const ScopedEnv noLimit(kImageLimitVariable, nullptr);
    const std::string exr = smallExr();
    std::size_t end = 0;
    exrAttributes(exr, &end);
    std::mt19937 rng(25);
    const auto start = std::chrono::steady_clock::now();
    int refused = 0;
    for (int i = 0; i < 300; ++i) {
        std::string b = exr;
        // Mostly the header and the offset table, where sizes come from.
        const std::size_t span = i % 3 == 0 ? b.size() : std::min(b.size(), end + 8 * 8 + 16);
        for (int k = 0; k < 1 + i % 4; ++k) b[rng() % span] = static_cast<char>(rng());
        if (i % 10 == 9) b.resize(rng() % b.size());
        const std::string e = imageError("corrupt.exr", b);
        EXPECT_EQ(e.find("not a FileError"), std::string::npos) << i << ": " << e;
        if (e != "no error") {
            ++refused;
            EXPECT_HAS(e, "corrupt.exr: ");
        }
    }
    EXPECT_GT(refused, 50);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
}

// docs/scene-format.md accepts any size > 0: a box 1e-12 across was refused
// ("mesh 'box': vertex 0 has a normal that does not fit 32-bit floats", the
// cross product of its edges underflowing), a cone 1e-40 high too (radius /
// height overflowing). Every shape at tiny and huge sizes has the unit
// normals and tangents of the same shape at size 1.
TEST(ReaderValidation, TinyAndHugeShapesHaveTheNormalsOfTheShapeAtSize1) {
    auto shape = [](const std::string& spec, double s, double t) {
        std::string text = spec;
        for (const auto& [key, value] : {std::pair<std::string, double>{"S", s}, {"T", t}})
            for (std::size_t at; (at = text.find("@" + key)) != std::string::npos;) {
                char buf[32];
                std::snprintf(buf, sizeof buf, "%.9g", value);
                text.replace(at, 2, buf);
            }
        return parseSceneJson(R"({"objects": [)" + text + "]}", "shape.json");
    };
    const std::vector<std::string> specs = {
        R"({"shape": "box", "size": [@S, @S, @S]})",        R"({"shape": "box", "size": [@S, @T, @S]})",
        R"({"shape": "plane", "size": [@S, 0, @S]})",       R"({"shape": "sphere", "radius": @S})",
        R"({"shape": "cylinder", "radius": @S, "height": @T})", R"({"shape": "cone", "radius": @S, "height": @T})"};
    for (const std::string& spec : specs) {
        const Scene unit = shape(spec, 1.0, 1.0);
        // Both sizes scaled alike, then the second one alone (a cone 1e-40 high).
        for (const auto& [s, t] : std::initializer_list<std::pair<double, double>>{
                 {1e-12, 1e-12}, {1e-20, 1e-20}, {1e-30, 1e-30}, {1e-37, 1e-37}, {1, 1e-40}, {1e-40, 1}, {1e18, 1e18}, {1, 1e-12}}) {
            const std::string what = spec + " at " + ::testing::PrintToString(s) + ", " + ::testing::PrintToString(t);
            Scene scene;
            try {
                scene = shape(spec, s, t);
            } catch (const std::exception& e) {
                ADD_FAILURE() << what << ": " << e.what();
                continue;
            }
            // The same proportions, the larger size 1.
            const double m = std::max(s, t);
            const Scene ref = s == t ? unit : shape(spec, s / m, t / m);
            ASSERT_EQ(scene.meshes.size(), 1u);
            const auto& got = scene.meshes[0].vertices;
            const auto& want = ref.meshes[0].vertices;
            ASSERT_EQ(got.size(), want.size()) << what;
            // Edges of denormal length (below 1.2e-38: the sphere's near its
            // poles at a radius under about 1e-34) keep fewer bits of their
            // positions, and the tangents derived from them follow.
            const bool denormal = std::min(s, t) < 1e-34;
            for (std::size_t v = 0; v < got.size(); ++v) {
                ASSERT_NEAR(glm::length(got[v].normal), 1.0f, 1e-5f) << what << " vertex " << v;
                ASSERT_GT(glm::dot(got[v].normal, want[v].normal), 0.99999f) << what << " vertex " << v;
                ASSERT_NEAR(glm::length(glm::vec3(got[v].tangent)), 1.0f, 1e-5f) << what << " vertex " << v;
                if (!denormal) {
                    ASSERT_GT(glm::dot(glm::vec3(got[v].tangent), glm::vec3(want[v].tangent)), 0.99f) << what << " vertex " << v;
                }
            }
        }
    }
    // Named by the message as given, refused only at 0 (docs/scene-format.md).
    EXPECT_HAS(sceneError(writeText("zero-cone.json", R"({"objects": [{"shape": "cone", "height": 0}]})")),
               "zero-cone.json: objects[0].height: must be greater than 0");
}

TEST(ReaderValidation, FieldsThatCombineBeyondAFloatAreRefused) {
    // Each number fits; the box's diagonal, and a camera framing it, do not.
    EXPECT_HAS(sceneError(writeText("huge.json", R"({"objects": [{"shape": "box", "size": [3e38, 3e38, 3e38]}]})")),
               "huge.json: the scene's extent");
    // A translation that fits, under a parent scale that carries it beyond a float.
    json j = triangleGltf();
    j["nodes"] = json::array({{{"scale", {1e30, 1e30, 1e30}}, {"children", {1}}}, {{"mesh", 0}, {"translation", {1e10, 0, 0}}}});
    EXPECT_HAS(gltfError("nested-scale.gltf", j), "nested-scale.gltf: ");
    EXPECT_EQ(gltfError("nested-scale.gltf", j).find("no error"), std::string::npos);
    // A box side of 0 has no face normal (found by fuzz_scene_json).
    EXPECT_HAS(sceneError(writeText("flat-box.json", R"({"objects": [{"shape": "box", "size": [0, 2, 1]}]})")),
               "flat-box.json: objects[0].size: every side must be greater than 0, got [0, 2, 1]");
    // A uv-scale that fits, times the plane's size, does not.
    EXPECT_HAS(sceneError(writeText("uv.json", R"({"objects": [{"shape": "plane", "size": [10, 0, 10], "uv-scale": 3e38}]})")),
               "uv.json: mesh 'plane': vertex 1 has a texture coordinate that does not fit 32-bit floats");
    // A walk-through keyframe looking straight down the scene camera's up.
    EXPECT_HAS(sceneError(writeText("path.json", scene(R"("camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0],
        "path": [{"time": 0, "pos": [0, 1, 5], "look-at": [0, 0, 0]}, {"time": 1, "pos": [0, 9, 0], "look-at": [0, 0, 0]}]})"))),
               "path.json: camera.path[1].look-at: looks along camera.up");
    // Both keyframes are fine, but pos moves through the fixed look-at point
    // between them, and in the other file the view turns through camera.up.
    EXPECT_HAS(sceneError(writeText("through.json", scene(R"("camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0],
        "path": [{"time": 0, "pos": [4, 2.5, 0], "look-at": [0, 2.5, 0]}, {"time": 2, "pos": [-4, 2.5, 0], "look-at": [0, 2.5, 0]}]})"))),
               "through.json: camera.path[1]: on the way from the keyframe before it, the camera reaches its look-at "
               "point (at time 1)");
    EXPECT_HAS(sceneError(writeText("over.json", scene(R"("camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0],
        "path": [{"time": 0, "pos": [-4, 5, 0], "look-at": [0, 0, 0]}, {"time": 1, "pos": [4, 5, 0], "look-at": [0, 0, 0]}]})"))),
               "over.json: camera.path[1]: on the way from the keyframe before it, the camera looks along camera.up "
               "(at time 0.5)");
}

// Values that each fit a float but overflow in combination (lights summed in
// the L-buffer, distances squared) and fields of view too narrow for float
// precision are refused, naming the light or field.
TEST(ReaderValidation, ValuesThatOverflowInCombinationAreRefused) {
    auto light = [](const std::string& name, const std::string& fields) {
        return sceneError(writeText(name, scene(R"("lights": [{"name": "L", "type": "point", "pos": [0, 2, 0], )" +
                                                fields + "}]")));
    };
    EXPECT_HAS(light("bright.json", R"("intensity": 3e38)"), "bright.json: light 'L': intensity 3e+38 is beyond 1e30");
    EXPECT_HAS(sceneError(writeText("far-light.json", scene(R"("lights": [{"name": "L", "type": "point", "pos": [3e38, 2, 0]}])"))),
               "far-light.json: light 'L': position 3e+38 is beyond 1e18 from the origin");
    EXPECT_HAS(light("tiny-constant.json", R"("intensity": 1e20, "attenuation": {"constant": 1e-30})"),
               "tiny-constant.json: light 'L': intensity / attenuation.constant = 1e+50 is beyond 1e30");
    EXPECT_HAS(sceneError(writeText("narrow.json", scene(R"("camera": {"pos": [0, 1, 5], "look-at": [0, 0, 0], "fov": 1e-30})"))),
               "narrow.json: camera.fov: must be at least 0.001 degrees");
    // The extremes the renderer keeps finite are still accepted.
    EXPECT_EQ(light("bright-ok.json", R"("intensity": 1e20)"), "no error");
}
