// glTF files rendered (issue 8): mirrored nodes keep their faces outward,
// the bitangent follows a mirroring transform, and the baked occlusion
// texture scales the ambient term as lighting.ambient_occlusion selects.
// The files are written by the tests (tests/support/GltfBuilder.h).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/support/GltfBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {


// A unit cube with one normal per face (24 vertices), counter-clockwise
// outward, as /work/shared/cases/inputs/negative_scale_mirror.gltf has it.
void addCube(test::GltfBuilder& b, int& position, int& normal, int& indices) {
    std::vector<float> p, n;
    std::vector<std::uint16_t> idx;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            glm::vec3 N(0.0f);
            N[axis] = static_cast<float>(sign);
            glm::vec3 U(0.0f), V(0.0f);
            U[(axis + 1) % 3] = 1.0f;
            V[(axis + 2) % 3] = 1.0f;
            if (sign < 0) std::swap(U, V);  // keep U x V = N
            const auto base = static_cast<std::uint16_t>(p.size() / 3);
            for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                const glm::vec3 q = 0.5f * (N + c.x * U + c.y * V);
                p.insert(p.end(), {q.x, q.y, q.z});
                n.insert(n.end(), {N.x, N.y, N.z});
            }
            for (int i : {0, 1, 2, 0, 2, 3}) idx.push_back(static_cast<std::uint16_t>(base + i));
        }
    position = b.vec3(p);
    normal = b.vec3(n);
    indices = b.indices(idx);
}

}  // namespace

// negative_scale_mirror.gltf: a cube and its mirror image (scale -1 on X).
// A pixel is back-facing when its normal points away from the eye.
TEST(GltfRender, MirroredNodeHasNoBackFacingPixels) {
    test::GltfBuilder b;
    int pos = 0, nrm = 0, idx = 0;
    addCube(b, pos, nrm, idx);
    json j = b.finish({{"POSITION", pos}, {"NORMAL", nrm}}, idx,
                      {{{"translation", {-1.2, 0, 0}}}, {{"translation", {1.2, 0, 0}}, {"scale", {-1, 1, 1}}}});
    auto session = test::makeSession(200, 150);
    session->loadScene(test::writeJson("mirror.gltf", j).string());
    session->render({{"gbuffer.view_normal", "gbuffer.view_position", "gbuffer.albedo"}});
    const FloatImage n = session->readRaw("gbuffer.view_normal");
    const FloatImage p = session->readRaw("gbuffer.view_position");
    const FloatImage albedo = session->readRaw("gbuffer.albedo");
    // The mirrored cube (+X) is on the right half of the frame: count each half.
    long long covered[2] = {0, 0}, backFacing[2] = {0, 0};
    for (int y = 0; y < n.height; ++y)
        for (int x = 0; x < n.width; ++x) {
            if (albedo.at(x, y, 3) < 0.5f / 255.0f) continue;
            const glm::vec3 N(n.at(x, y, 0), n.at(x, y, 1), n.at(x, y, 2));
            const glm::vec3 toEye = -glm::normalize(glm::vec3(p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2)));
            const int half = x < n.width / 2 ? 0 : 1;
            ++covered[half];
            // Quantised normals at grazing angles may dip a little below zero.
            if (glm::dot(N, toEye) < -0.02f) ++backFacing[half];
        }
    std::printf("covered %lld / %lld pixels, back-facing %lld / %lld\n", covered[0], covered[1], backFacing[0],
                backFacing[1]);
    ASSERT_GT(covered[0], 500);
    ASSERT_GT(covered[1], 500);
    EXPECT_EQ(backFacing[0], 0);
    EXPECT_EQ(backFacing[1], 0);
}

// The same normal-mapped quad, plain and mirrored on X: the mirrored render's
// view-space normals are the plain one's with x negated, pixel for pixel
// (mirrored left-right), because the bitangent sign follows the transform.
TEST(GltfRender, NormalMapUnderAMirroringTransformIsTheMirrorImage) {
    // A normal map tilted towards +U (+X in texture space): (0.5, 0, 0.87).
    FloatImage tilt;
    tilt.width = tilt.height = 4;
    tilt.channels = 4;
    for (int i = 0; i < 16; ++i) tilt.pixels.insert(tilt.pixels.end(), {0.75f, 0.5f, 0.933f, 1.0f});
    writeImage((test::tempDir() / "tilt.png").string(), tilt);
    auto render = [&](float scaleX) {
        test::GltfBuilder b;
        const int pos = b.vec3({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});
        const int nrm = b.vec3({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
        const int uv = b.accessor(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}, 5126, "VEC2", 4);
        const int idx = b.indices({0, 1, 2, 0, 2, 3});
        json j = b.finish({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}, idx,
                          {{{"scale", {scaleX, 1, 1}}}});
        j["images"] = json::array({{{"uri", "tilt.png"}}});
        j["textures"] = json::array({{{"source", 0}}});
        j["materials"] = json::array({{{"normalTexture", {{"index", 0}}}}});
        j["meshes"][0]["primitives"][0]["material"] = 0;
        j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}, {"zfar", 20}}}}});
        j["nodes"].push_back({{"translation", {0, 0, 3}}, {"camera", 0}});
        j["scenes"][0]["nodes"].push_back(1);
        auto session = test::makeSession(64, 64);
        session->loadScene(test::writeJson(scaleX < 0 ? "tilt_mirrored.gltf" : "tilt.gltf", j).string());
        session->render({{"gbuffer.view_normal"}});
        return session->readRaw("gbuffer.view_normal");
    };
    const FloatImage plain = render(1.0f), mirrored = render(-1.0f);
    const float cx = plain.at(32, 32, 0);
    EXPECT_GT(cx, 0.4f);  // the tilt is visible: towards +X in the plain render
    double worst = 0.0;
    for (int y = 14; y < 50; ++y)
        for (int x = 14; x < 50; ++x) {
            const int mx = plain.width - 1 - x;
            worst = std::max({worst, std::fabs(double(mirrored.at(mx, y, 0)) + plain.at(x, y, 0)),
                              std::fabs(double(mirrored.at(mx, y, 1)) - plain.at(x, y, 1)),
                              std::fabs(double(mirrored.at(mx, y, 2)) - plain.at(x, y, 2))});
        }
    EXPECT_LT(worst, 0.02);
}

// A quad under ambient light only, its occlusion texture 50% grey (R = 0.5,
// strength 1): gbuffer.occlusion holds 0.5 and the ambient term halves with
// lighting.ambient_occlusion = baked or both, and stays whole with screen.
TEST(GltfRender, OcclusionTextureScalesTheAmbientTermAsTheKnobSays) {
    FloatImage grey;
    grey.width = grey.height = 4;
    grey.channels = 4;
    for (int i = 0; i < 16; ++i) grey.pixels.insert(grey.pixels.end(), {0.5f, 0.5f, 0.5f, 1.0f});
    writeImage((test::tempDir() / "grey.png").string(), grey);
    test::GltfBuilder b;
    const int pos = b.vec3({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});
    const int nrm = b.vec3({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    const int uv = b.accessor(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0}, 5126, "VEC2", 4);
    const int idx = b.indices({0, 1, 2, 0, 2, 3});
    json j = b.finish({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}, idx);
    j["images"] = json::array({{{"uri", "grey.png"}}});
    j["textures"] = json::array({{{"source", 0}}});
    j["materials"] = json::array({{{"occlusionTexture", {{"index", 0}}}}});
    j["meshes"][0]["primitives"][0]["material"] = 0;
    j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 20}}}}});
    j["nodes"].push_back({{"translation", {0, 0, 3}}, {"camera", 0}});
    j["scenes"][0]["nodes"].push_back(1);
    auto session = test::makeSession(48, 48);
    session->loadScene(test::writeJson("occlusion.gltf", j).string());
    // Ambient light only: without the default light rig a glTF without lights gets.
    Scene ambientOnly = session->scene();
    ambientOnly.lights.clear();
    session->setScene(std::move(ambientOnly));
    auto ambientAt = [&](const char* mode) {
        session->knobs().setFromString("ao.enabled", "false");
        session->knobs().setFromString("lighting.ambient_occlusion", mode);
        session->render({{"lbuffer", "gbuffer.occlusion"}});
        return session->readRaw("lbuffer").at(24, 24, 1);
    };
    const float ssaoOnly = ambientAt("screen");
    const float both = ambientAt("both");
    const float occlusion = session->readRaw("gbuffer.occlusion").at(24, 24, 0);
    const float baked = ambientAt("baked");
    std::printf("ambient: ssao %.5f, baked %.5f, both %.5f; gbuffer.occlusion %.4f\n", ssaoOnly, baked, both, occlusion);
    EXPECT_NEAR(occlusion, 0.5f, 2.0f / 255.0f);
    ASSERT_GT(ssaoOnly, 0.0f);
    EXPECT_NEAR(baked / ssaoOnly, occlusion, 0.01f);
    EXPECT_NEAR(both / ssaoOnly, occlusion, 0.01f);
}

// tests/data/gltf/split_corner_tangents.gltf (make_split_corners.py): a 2 x 2
// grid of quads facing +Z whose centre vertex's normal faces away from its six
// triangles; TANGENT is +Y everywhere but (0, -1, 0) at the centre. With a
// normal map tilted towards +U (+T), each pixel's normal tilts along its
// interpolated tangent: -Y around the centre only if the split corners kept
// the centre's tangent (+X if they got a generated one, +Y a neighbour's).
// The file was refused before ("TANGENT has 9 elements but POSITION has 15").
TEST(GltfRender, SplitCornersRenderWithTheirOwnTangent) {
    FloatImage tilt;
    tilt.width = tilt.height = 4;
    tilt.channels = 4;
    for (int i = 0; i < 16; ++i) tilt.pixels.insert(tilt.pixels.end(), {0.75f, 0.5f, 0.933f, 1.0f});
    writeImage((test::tempDir() / "split_tilt.png").string(), tilt);
    json j;
    std::ifstream(fs::path(DW_TEST_GLTF_DIR) / "split_corner_tangents.gltf") >> j;
    j["images"] = json::array({{{"uri", "split_tilt.png"}}});
    j["textures"] = json::array({{{"source", 0}}});
    j["materials"] = json::array({{{"normalTexture", {{"index", 0}}}}});
    j["meshes"][0]["primitives"][0]["material"] = 0;
    j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}, {"zfar", 20}}}}});
    j["nodes"].push_back({{"translation", {1, 1, 3}}, {"camera", 0}});
    j["scenes"][0]["nodes"].push_back(1);
    auto session = test::makeSession(64, 64);
    session->loadScene(test::writeJson("split_corner_tilt.gltf", j).string());
    session->render({{"gbuffer.view_normal"}});
    const FloatImage n = session->readRaw("gbuffer.view_normal");
    // The grid spans about 12..52 in both axes; its centre vertex is at (32, 32).
    const glm::vec3 centre(n.at(32, 32, 0), n.at(32, 32, 1), n.at(32, 32, 2));
    std::printf("view normal at the split centre (%.3f, %.3f, %.3f)\n", centre.x, centre.y, centre.z);
    EXPECT_LT(centre.y, -0.4f);  // tilted along the centre's own tangent, -Y
    EXPECT_NEAR(centre.x, 0.0f, 0.05f);
    EXPECT_GT(centre.z, 0.8f);
    // Near the grid's outer corners the tangent is the others' +Y.
    for (const auto& [x, y] : {std::pair{15, 15}, std::pair{48, 15}, std::pair{15, 48}, std::pair{48, 48}}) {
        EXPECT_GT(n.at(x, y, 1), 0.4f) << x << ", " << y;
        EXPECT_NEAR(n.at(x, y, 0), 0.0f, 0.05f) << x << ", " << y;
    }
}
