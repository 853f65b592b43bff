#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "renderer/Error.h"
#include "renderer/scene/GltfLoader.h"
#include "renderer/scene/SceneLoader.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string base64(const std::vector<unsigned char>& data) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < data.size(); i += 3) {
        const unsigned v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
        out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
    }
    if (i + 1 == data.size()) {
        const unsigned v = data[i] << 16;
        out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == data.size()) {
        const unsigned v = (data[i] << 16) | (data[i + 1] << 8);
        out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
    }
    return out;
}

template <typename T>
void append(std::vector<unsigned char>& buf, const std::vector<T>& values) {
    const size_t at = buf.size();
    buf.resize(at + values.size() * sizeof(T));
    std::memcpy(buf.data() + at, values.data(), values.size() * sizeof(T));
}

// A one-triangle glTF; `edit` breaks it in a specific way before it is written.
struct TriangleGltf {
    std::vector<float> positions{0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::vector<uint16_t> indices{0, 1, 2};
    json doc;

    json build() {
        std::vector<unsigned char> buf;
        append(buf, positions);
        const size_t posBytes = buf.size();
        append(buf, indices);
        buf.resize((buf.size() + 3) & ~size_t(3));
        json j;
        j["asset"] = {{"version", "2.0"}};
        j["buffers"] = json::array({{{"byteLength", buf.size()},
                                     {"uri", "data:application/octet-stream;base64," + base64(buf)}}});
        j["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", posBytes}},
                                        {{"buffer", 0}, {"byteOffset", posBytes}, {"byteLength", indices.size() * 2}}});
        j["accessors"] = json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", positions.size() / 3},
                                       {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                                      {{"bufferView", 1}, {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}}});
        j["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}})}}});
        j["nodes"] = json::array({{{"mesh", 0}}});
        j["scenes"] = json::array({{{"nodes", {0}}}});
        j["scene"] = 0;
        return j;
    }
};

fs::path write(const std::string& name, const json& j) {
    const fs::path p = test::tempDir() / name;
    std::ofstream(p) << j.dump(1);
    return p;
}

std::string errorOf(const fs::path& p) {
    try {
        Scene s;
        importGltf(p.string(), s, glm::mat4(1.0f), true);
    } catch (const FileError& e) {
        EXPECT_EQ(e.path(), p.string());
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(GltfLoader, LoadsAValidTriangleAndGeneratesNormalsAndTangents) {
    TriangleGltf t;
    const fs::path p = write("triangle.gltf", t.build());
    Scene s;
    const GltfImport r = importGltf(p.string(), s, glm::mat4(1.0f), true);
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.meshes[0].vertices.size(), 3u);
    EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_NEAR(s.meshes[0].vertices[0].normal.z, 1.0f, 1e-6f);  // counter-clockwise in XY faces +Z
    EXPECT_NEAR(glm::length(glm::vec3(s.meshes[0].vertices[0].tangent)), 1.0f, 1e-5f);
    EXPECT_FALSE(r.hasCamera);
    EXPECT_FLOAT_EQ(r.bounds.max.y, 1.0f);
}

TEST(GltfLoader, IndexOutOfRangeIsAnError) {
    TriangleGltf t;
    t.indices = {0, 1, 7};
    EXPECT_NE(errorOf(write("index.gltf", t.build())).find("index 7 is out of range (3 vertices)"), std::string::npos);
}

TEST(GltfLoader, AccessorPastItsBufferViewIsAnError) {
    TriangleGltf t;
    json j = t.build();
    j["accessors"][0]["count"] = 30;
    EXPECT_NE(errorOf(write("accessor.gltf", j)).find("accessor[0] reads"), std::string::npos);
    j = t.build();
    j["accessors"][0]["count"] = 4000000000ull;
    EXPECT_NE(errorOf(write("count.gltf", j)).find("implausibly large"), std::string::npos);
    j = t.build();
    j["bufferViews"][1]["byteLength"] = 100000;
    EXPECT_NE(errorOf(write("view.gltf", j)).find("runs past the end of buffer[0]"), std::string::npos);
}

TEST(GltfLoader, NodeCyclesAndBadReferencesAreErrors) {
    TriangleGltf t;
    json j = t.build();
    j["nodes"] = json::array({{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}});
    const std::string cycle = errorOf(write("cycle.gltf", j));
    EXPECT_TRUE(cycle.find("cycle") != std::string::npos || cycle.find("two parents") != std::string::npos) << cycle;
    j = t.build();
    j["nodes"][0]["mesh"] = 3;
    EXPECT_NE(errorOf(write("mesh.gltf", j)).find("node[0].mesh refers to index 3"), std::string::npos);
    j = t.build();
    j["nodes"] = json::array({{{"mesh", 0}, {"children", {0}}}});
    EXPECT_NE(errorOf(write("self.gltf", j)).find("lists itself"), std::string::npos);
}

TEST(GltfLoader, NonFinitePositionsAreErrors) {
    TriangleGltf t;
    t.positions[4] = std::numeric_limits<float>::infinity();
    EXPECT_NE(errorOf(write("inf.gltf", t.build())).find("non-finite"), std::string::npos);
    t.positions[4] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(errorOf(write("nan.gltf", t.build())).find("non-finite"), std::string::npos);
}

TEST(GltfLoader, MissingBinaryAndTextureFilesAreNamed) {
    TriangleGltf t;
    json j = t.build();
    j["buffers"][0]["uri"] = "geometry.bin";
    EXPECT_NE(errorOf(write("nobin.gltf", j)).find("geometry.bin"), std::string::npos);
    j = t.build();
    j["images"] = json::array({{{"uri", "textures/missing.png"}}});
    j["textures"] = json::array({{{"source", 0}}});
    j["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    j["meshes"][0]["primitives"][0]["material"] = 0;
    const std::string e = errorOf(write("notex.gltf", j));
    EXPECT_NE(e.find("missing texture"), std::string::npos) << e;
    EXPECT_NE(e.find("textures/missing.png"), std::string::npos) << e;
}

TEST(GltfLoader, ExternalFilesThatAreDevicesPipesOrFoldersAreRefusedByNameNotReadForever) {
    // Issue 32's kind "a path that is not a file": an image or buffer URI
    // naming /dev/zero (through a link), a pipe with no writer or a folder is
    // read through the bounded reader and named as what it is (tinygltf's
    // own reader said "missing texture", or waited forever on the pipe).
    const fs::path zero = test::tempDir() / "zero.png";
    fs::remove(zero);
    fs::create_symlink("/dev/zero", zero);
    const fs::path fifo = test::tempDir() / "no-writer.bin";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    fs::create_directories(test::tempDir() / "folder.png");
    const auto start = std::chrono::steady_clock::now();
    TriangleGltf t;
    const fs::path pipe = test::tempDir() / "pipe.png";
    fs::remove(pipe);
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    // A writer that stays and never writes: a read would wait for it forever.
    const int writer = ::open(pipe.c_str(), O_RDWR | O_CLOEXEC);
    ASSERT_GE(writer, 0);
    for (const std::string uri : {"zero.png", "folder.png", "pipe.png"}) {
        json j = t.build();
        j["images"] = json::array({{{"uri", uri}}});
        j["textures"] = json::array({{{"source", 0}}});
        j["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
        j["meshes"][0]["primitives"][0]["material"] = 0;
        const std::string e = errorOf(write("device-image.gltf", j));
        EXPECT_NE(e.find("image[0] '" + uri + "' cannot be read"), std::string::npos) << e;
        const std::string what = uri == "zero.png"     ? "it is a device, not a file"
                                 : uri == "folder.png" ? "it is a folder, not a file"
                                                       : "it is a pipe or socket, not a file";
        EXPECT_NE(e.find(what), std::string::npos) << e;
        EXPECT_EQ(e.find("missing texture"), std::string::npos) << e;
    }
    json j = t.build();
    j["buffers"][0]["uri"] = "pipe.png";  // a buffer on the pipe with a writer
    const std::string e = errorOf(write("pipe-buffer.gltf", j));
    EXPECT_NE(e.find("pipe.png"), std::string::npos) << e;
    EXPECT_NE(e.find("it is a pipe or socket, not a file"), std::string::npos) << e;
    j["buffers"][0]["uri"] = "no-writer.bin";
    const std::string none = errorOf(write("no-writer-buffer.gltf", j));
    EXPECT_NE(none.find("no-writer.bin"), std::string::npos) << none;
    ::close(writer);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(GltfLoader, MalformedJsonAndUnsupportedExtensions) {
    const fs::path p = test::tempDir() / "truncated.gltf";
    std::ofstream(p) << "{\"asset\": {\"version\": \"2.0\"},\n \"meshes\": [";
    EXPECT_NE(errorOf(p).find("malformed JSON at line 2"), std::string::npos);
    TriangleGltf t;
    json j = t.build();
    j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    EXPECT_NE(errorOf(write("draco.gltf", j)).find("requires glTF extension KHR_draco_mesh_compression"),
              std::string::npos);
    const fs::path garbage = test::tempDir() / "garbage.glb";
    std::ofstream(garbage, std::ios::binary) << "glTF\x02\0\0\0garbage";
    EXPECT_NE(errorOf(garbage), "no error");
}

TEST(GltfLoader, ImportsPunctualLightsAndCamera) {
    TriangleGltf t;
    json j = t.build();
    j["extensionsUsed"] = {"KHR_lights_punctual"};
    j["extensions"]["KHR_lights_punctual"]["lights"] =
        json::array({{{"type", "spot"}, {"color", {1, 0.5, 0.25}}, {"intensity", 4},
                      {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}}});
    j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.05}, {"zfar", 50}}}}});
    j["nodes"].push_back({{"translation", {0, 3, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    j["nodes"].push_back({{"translation", {0, 0, 5}}, {"camera", 0}});
    j["scenes"][0]["nodes"] = {0, 1, 2};
    Scene s;
    const GltfImport r = importGltf(write("lights.gltf", j).string(), s, glm::mat4(1.0f), true);
    ASSERT_EQ(r.lightCount, 1);
    EXPECT_EQ(s.lights[0].type, LightType::Spot);
    EXPECT_NEAR(s.lights[0].position.y, 3.0f, 1e-6f);
    EXPECT_NEAR(s.lights[0].direction.z, -1.0f, 1e-6f);  // glTF lights point down -Z
    EXPECT_NEAR(s.lights[0].cutoffDegrees, glm::degrees(0.6f), 1e-3f);
    // The extension's falloff, not an exponent fitted to it.
    EXPECT_EQ(s.lights[0].falloff, SpotFalloff::InnerOuterCone);
    EXPECT_NEAR(s.lights[0].innerConeDegrees, glm::degrees(0.2f), 1e-3f);
    EXPECT_NEAR(s.lights[0].intensity.g, 2.0f, 1e-6f);
    EXPECT_TRUE(r.hasCamera);
    EXPECT_NEAR(s.camera.fovYDegrees, glm::degrees(0.8f), 1e-3f);
    EXPECT_NEAR(s.camera.position.z, 5.0f, 1e-6f);
    // No range: nothing said of it.
    for (const auto& w : s.warnings) EXPECT_EQ(w.find("range"), std::string::npos) << w;

    // A light's range is not silently dropped: the warning says it is not used.
    j["extensions"]["KHR_lights_punctual"]["lights"][0]["range"] = 3.5;
    Scene ranged;
    importGltf(write("ranged.gltf", j).string(), ranged, glm::mat4(1.0f), true);
    bool said = false;
    for (const auto& w : ranged.warnings)
        said |= w.find("ignored (not supported by the workbench)") != std::string::npos &&
                w.find("KHR_lights_punctual range on 1 light(s)") != std::string::npos;
    EXPECT_TRUE(said) << "the range went unmentioned";
}

TEST(GltfLoader, SharedSampleModelsLoad) {
    const fs::path dir = test::dataDir() / "gltf";
    if (!fs::exists(dir)) GTEST_SKIP() << "no shared data at " << dir;
    struct Expect {
        const char* file;
        size_t minTriangles;
        size_t images;
    };
    const Expect expected[] = {{"BoxTextured/BoxTextured.gltf", 12, 1},
                               {"Duck/Duck.gltf", 4000, 1},
                               {"NormalTangentTest/NormalTangentTest.gltf", 100, 3},
                               {"bunny/bunny.gltf", 60000, 0},
                               {"dragon_res2.glb", 100000, 0},
                               {"AlphaBlendModeTest/AlphaBlendModeTest.gltf", 10, 1}};
    for (const auto& e : expected) {
        const Scene s = loadScene((dir / e.file).string());
        EXPECT_GE(s.triangleCount(), e.minTriangles) << e.file;
        EXPECT_GE(s.images.size(), e.images) << e.file;
        EXPECT_FALSE(s.lights.empty()) << e.file << " should get the default light rig";
    }
    const Scene alpha = loadScene((dir / "AlphaBlendModeTest/AlphaBlendModeTest.gltf").string());
    EXPECT_TRUE(alpha.hasMaterial(AlphaMode::Blend));
    EXPECT_TRUE(alpha.hasMaterial(AlphaMode::Mask));
}

TEST(GltfLoader, AssimpBrokenModelsGiveClearErrors) {
    const fs::path dir = "/usr/share/assimp/models/glTF2";
    if (!fs::exists(dir)) GTEST_SKIP() << "assimp-testmodels is not installed";
    const std::pair<const char*, const char*> broken[] = {
        {"IndexOutOfRange/IndexOutOfRange.gltf", "out of range"},
        {"IndexOutOfRange/AllIndicesOutOfRange.gltf", "out of range"},
        {"RecursiveNodes/RecursiveNodes.gltf", "cycle"},
        {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "non-finite"},
        {"MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
        {"IncorrectVertexArrays/Cube.gltf", "runs past the end"},
        {"draco/2CylinderEngine.gltf", "KHR_draco_mesh_compression"},
    };
    for (const auto& [file, expect] : broken) {
        const std::string e = errorOf(dir / file);
        EXPECT_NE(e.find(expect), std::string::npos) << file << ": " << e;
    }
    for (const char* ok : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb",
                           "BoxTextured-glTF-Embedded/BoxTextured.gltf", "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf",
                           "2CylinderEngine-glTF-Binary/2CylinderEngine.glb"}) {
        Scene s;
        EXPECT_NO_THROW(importGltf((dir / ok).string(), s, glm::mat4(1.0f), true)) << ok;
        EXPECT_FALSE(s.instances.empty()) << ok;
    }
}

// Issue 25: what tinygltf refuses without a reason (a skin without joints),
// or drops silently (a texture reference without index, a primitive without
// attributes), is named by the object and the property the spec requires.
TEST(GltfLoader, MissingRequiredPropertiesAreNamedByObject) {
    TriangleGltf t;
    json j = t.build();
    j["nodes"].push_back(json::object());
    j["skins"] = json::array({{{"inverseBindMatrices", 0}}});
    std::string e = errorOf(write("skin.gltf", j));
    EXPECT_NE(e.find("skin.gltf: skins[0]: required property 'joints' is missing"), std::string::npos) << e;
    EXPECT_EQ(e.find("without giving a reason"), std::string::npos) << e;
    j["skins"] = json::array({{{"joints", json::array()}}});
    e = errorOf(write("skin-empty.gltf", j));
    EXPECT_NE(e.find("skins[0].joints: must not be empty"), std::string::npos) << e;

    j = t.build();
    j["accessors"][0].erase("count");
    j["accessors"][1].erase("componentType");
    j["accessors"][1].erase("type");
    e = errorOf(write("accessors.gltf", j));
    EXPECT_NE(e.find("accessors[0]: required property 'count' is missing; accessors[1]: required property 'componentType' "
                     "is missing; accessors[1]: required property 'type' is missing"),
              std::string::npos)
        << e;

    j = t.build();
    j["bufferViews"][0].erase("byteLength");
    j["buffers"][0].erase("byteLength");
    j["meshes"][0]["primitives"].push_back({{"indices", 1}});
    j["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"texCoord", 0}}}}}}});
    j["cameras"] = json::array({{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}}}}});
    e = errorOf(write("several.gltf", j));
    for (const char* part : {"buffers[0]: required property 'byteLength' is missing",
                             "bufferViews[0]: required property 'byteLength' is missing",
                             "meshes[0].primitives[1]: required property 'attributes' is missing",
                             "materials[0].pbrMetallicRoughness.baseColorTexture: required property 'index' is missing",
                             "cameras[0].orthographic: required property 'zfar' is missing"})
        EXPECT_NE(e.find(part), std::string::npos) << part << " missing from: " << e;
}

// Issue 25: offsets, lengths, counts and indices are integers: a value beyond
// a float, negative, fractional or past what the reader stores is named as
// an integer out of range, never "does not fit a 32-bit float".
TEST(GltfLoader, IntegerPropertiesAreCheckedAsIntegers) {
    TriangleGltf t;
    auto withText = [&](const std::string& name, const std::string& field, const std::string& number) {
        json j = t.build();
        j["bufferViews"][1][field] = 12345;
        std::string text = j.dump();
        const std::string key = "\"" + field + "\":12345";
        text.replace(text.find(key), key.size(), "\"" + field + "\":" + number);
        const fs::path p = test::tempDir() / name;
        std::ofstream(p) << text;
        return errorOf(p);
    };
    std::string e = withText("big.gltf", "byteLength", "1e39");
    EXPECT_NE(e.find("big.gltf: bufferViews[1].byteLength: 1e39 is out of range (a byte length from 1 to 9007199254740991)"),
              std::string::npos)
        << e;
    EXPECT_EQ(e.find("32-bit float"), std::string::npos) << e;
    e = withText("huge.gltf", "byteOffset", "1e400");
    EXPECT_NE(e.find("bufferViews[1].byteOffset: 1e400 is out of range (a byte offset from 0"), std::string::npos) << e;
    // Whole numbers the parser keeps as doubles (past 64 bits, or in exponent form) are integers too big.
    e = withText("u64.gltf", "byteLength", "18446744073709551616");
    EXPECT_NE(e.find("bufferViews[1].byteLength: 1.8446744073709552e+19 is out of range (a byte length"), std::string::npos) << e;
    e = withText("e20.gltf", "byteLength", "1e20");
    EXPECT_NE(e.find("bufferViews[1].byteLength: 1e+20 is out of range (a byte length"), std::string::npos) << e;
    e = withText("frac.gltf", "byteLength", "6.5");
    EXPECT_NE(e.find("bufferViews[1].byteLength: expected an integer, got 6.5"), std::string::npos) << e;
    e = withText("neg.gltf", "byteOffset", "-4");
    EXPECT_NE(e.find("bufferViews[1].byteOffset: -4 is out of range (a byte offset from 0 to 9007199254740991)"),
              std::string::npos)
        << e;
    e = withText("stride.gltf", "byteStride", "6");
    EXPECT_NE(e.find("bufferViews[1].byteStride: 6 is not a multiple of 4"), std::string::npos) << e;

    json j = t.build();
    j["nodes"][0]["mesh"] = 4294967296ull;  // an int would wrap it to 0
    e = errorOf(write("wrap.gltf", j));
    EXPECT_NE(e.find("nodes[0].mesh: 4294967296 is out of range (an index from 0 to 2147483647)"), std::string::npos) << e;
    j = t.build();
    j["accessors"][0]["count"] = 0;
    j["accessors"][1]["componentType"] = 5127;
    j["meshes"][0]["primitives"][0]["indices"] = "1";
    j["meshes"][0]["primitives"][0]["mode"] = 9;
    e = errorOf(write("ints.gltf", j));
    for (const char* part : {"accessors[0].count: 0 is out of range (a count from 1 to 9007199254740991)",
                             "accessors[1].componentType: 5127 is not one of 5120 (BYTE)",
                             "meshes[0].primitives[0].indices: expected an integer, got \"1\"",
                             "meshes[0].primitives[0].mode: 9 is out of range (a primitive mode (0 POINTS to 6 TRIANGLE_FAN)"})
        EXPECT_NE(e.find(part), std::string::npos) << part << " missing from: " << e;
}

// Issue 25: every invalid camera and light is named, not only the last.
TEST(GltfLoader, EveryInvalidCameraAndLightIsNamed) {
    TriangleGltf t;
    json j = t.build();
    j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0}, {"znear", 0.1}}}},
                                {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}},
                                {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", -1}}}}});
    j["extensions"]["KHR_lights_punctual"]["lights"] =
        json::array({{{"type", "point"}, {"intensity", -1}}, {{"type", "laser"}}, {{"type", "point"}}});
    const std::string e = errorOf(write("cameras.gltf", j));
    EXPECT_NE(e.find("cameras.gltf: cameras[0].perspective.yfov: must be in (0, 179) degrees, got 0 rad (0 degrees); "
                     "cameras[2].perspective.znear: must be greater than 0, got -1; "
                     "extensions.KHR_lights_punctual.lights[0].intensity: must not be negative, got -1; "
                     "extensions.KHR_lights_punctual.lights[1].type: expected \"directional\", \"point\" or \"spot\", got \"laser\""),
              std::string::npos)
        << e;
    EXPECT_EQ(e.find("cameras[1]"), std::string::npos) << e;
    // Many problems: the first twelve and a count of the rest, on one line.
    j = t.build();
    for (int i = 0; i < 15; ++i) j["cameras"].push_back({{"type", "perspective"}, {"perspective", {{"yfov", 0}, {"znear", 0.1}}}});
    const std::string many = errorOf(write("many.gltf", j));
    EXPECT_NE(many.find("cameras[11].perspective.yfov"), std::string::npos) << many;
    EXPECT_EQ(many.find("cameras[12]"), std::string::npos) << many;
    EXPECT_NE(many.find("; and 3 more"), std::string::npos) << many;
    EXPECT_EQ(many.find('\n'), std::string::npos) << many;
}

// Issue 25: the checks after parsing (ranges, references) name every bad
// object too, not only the first.
TEST(GltfLoader, EveryBadAccessorAndReferenceIsNamed) {
    TriangleGltf t;
    json j = t.build();
    j["accessors"][0]["count"] = 30;
    j["accessors"][1]["count"] = 40;
    j["nodes"].push_back({{"mesh", 7}});
    const std::string e = errorOf(write("accessors-range.gltf", j));
    EXPECT_NE(e.find("accessors-range.gltf: accessor[0] reads 360 bytes but bufferView[0] has only 36; "
                     "accessor[1] reads 80 bytes but bufferView[1] has only 6; node[1].mesh refers to index 7 but there are only 1"),
              std::string::npos)
        << e;
}
