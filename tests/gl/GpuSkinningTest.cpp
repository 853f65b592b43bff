// Issue 36: skinning and morphing as one compute dispatch in the scene layer
// (renderer/scene/GpuSkinning.h). The pose at 0.5 s reached by the GPU alone
// (the scene uploaded at 0 s, then only joint matrices and morph weights sent)
// gives the G-buffer (view positions and normals) the CPU's posed vertices
// give when uploaded, to float rounding; and that pose is not the one at 0 s
// (so a dispatch that wrote nothing would fail). On the test's own animated
// glTF (tests/support/AnimatedGltf.h) and the skinned and morphed samples of
// assimp-testmodels (skipped without them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <filesystem>

#include "renderer/RunConfig.h"
#include "renderer/scene/ScenePose.h"
#include "tests/support/AnimatedGltf.h"
#include "tests/support/GltfBuilder.h"
#include "tests/support/TestSupport.h"

namespace dw {
namespace {

constexpr int kW = 160, kH = 90;

// A skinned and morphed n x n grid in the XY plane, [0, 1]^2: joint 0 at the
// origin, joint 1 at (0, 0.5, 0) rotating 0 to 90 degrees about +Z over 1 s;
// a vertex at height y weights joint 1 by y; one morph target moving every
// vertex by (0, 0, 0.2), its weight 0 to 1 over 1 s.
nlohmann::json skinnedGrid(int n) {
    test::GltfBuilder b;
    std::vector<float> pos, nrm, weights, delta;
    std::vector<std::uint16_t> joints;
    std::vector<std::uint32_t> idx;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = static_cast<float>(i) / (n - 1), y = static_cast<float>(j) / (n - 1);
            pos.insert(pos.end(), {x, y, 0.0f});
            nrm.insert(nrm.end(), {0.0f, 0.0f, 1.0f});
            joints.insert(joints.end(), {0, 1, 0, 0});
            weights.insert(weights.end(), {1.0f - y, y, 0.0f, 0.0f});
            delta.insert(delta.end(), {0.0f, 0.0f, 0.2f});
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const auto v = static_cast<std::uint32_t>(j * n + i), w = static_cast<std::uint32_t>(n);
            idx.insert(idx.end(), {v, v + 1, v + w + 1, v, v + w + 1, v + w});
        }
    const auto count = static_cast<std::size_t>(n) * n;
    const int p = b.vec3(pos), nr = b.vec3(nrm), d = b.vec3(delta);
    const int ix = b.accessor(idx, 5125, "SCALAR", idx.size());
    const int jt = b.accessor(joints, 5123, "VEC4", count), wt = b.accessor(weights, 5126, "VEC4", count);
    const int ibm = b.accessor(std::vector<float>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,  //
                                                  1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -0.5f, 0, 1},
                               5126, "MAT4", 2);
    const int times = b.accessor(std::vector<float>{0, 1}, 5126, "SCALAR", 2);
    const float h = static_cast<float>(std::sqrt(0.5));
    const int rotations = b.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, h, h}, 5126, "VEC4", 2);
    const int morphWeights = b.accessor(std::vector<float>{0, 1}, 5126, "SCALAR", 2);
    nlohmann::json j = b.finish({{"POSITION", p}}, ix);
    nlohmann::json prim = {{"attributes", {{"POSITION", p}, {"NORMAL", nr}, {"JOINTS_0", jt}, {"WEIGHTS_0", wt}}},
                           {"indices", ix}};
    prim["targets"] = nlohmann::json::array({{{"POSITION", d}}});
    j["meshes"] = nlohmann::json::array({{{"primitives", nlohmann::json::array({prim})}}});
    j["nodes"] = nlohmann::json::array({{{"mesh", 0}, {"skin", 0}}, {{"children", {2}}}, {{"translation", {0, 0.5, 0}}}});
    j["skins"] = nlohmann::json::array({{{"joints", {1, 2}}, {"inverseBindMatrices", ibm}}});
    j["scenes"] = nlohmann::json::array({{{"nodes", {0, 1}}}});
    j["animations"] = nlohmann::json::array(
        {{{"name", "bend"},
          {"samplers", {{{"input", times}, {"output", rotations}}, {{"input", times}, {"output", morphWeights}}}},
          {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}},
                        {{"sampler", 1}, {"target", {{"node", 0}, {"path", "weights"}}}}}}}});
    return j;
}

struct GBuffer {
    FloatImage position, normal;
};

// The largest per-channel difference of two images, over pixels where both
// hold a surface (|view position| > 0), and how many pixels hold one in `a` only or `b` only.
struct Difference {
    double max = 0.0;
    int coverageDiffers = 0;
    int changed = 0;  // pixels whose coverage differs or whose value differs by over 1e-3
};

Difference compare(const FloatImage& a, const FloatImage& b) {
    Difference d;
    for (std::size_t p = 0; p < static_cast<std::size_t>(a.width) * a.height; ++p) {
        const float* x = &a.pixels[p * a.channels];
        const float* y = &b.pixels[p * b.channels];
        const bool sx = x[2] != 0.0f, sy = y[2] != 0.0f;  // view z: 0 where no surface
        if (sx != sy) ++d.coverageDiffers;
        if (!sx || !sy) {
            d.changed += sx != sy ? 1 : 0;
            continue;
        }
        double m = 0.0;
        for (int c = 0; c < std::min(a.channels, 3); ++c) m = std::max(m, static_cast<double>(std::abs(x[c] - y[c])));
        d.max = std::max(d.max, m);
        d.changed += m > 1e-3 ? 1 : 0;
    }
    return d;
}

GBuffer read(RenderSession& s) {
    FrameRequest request;
    request.outputs = {"gbuffer.view_position", "gbuffer.normal"};
    s.render(request);
    return {s.readRaw("gbuffer.view_position"), s.readRaw("gbuffer.normal")};
}

std::unique_ptr<RenderSession> sessionAt(const std::string& scene, double seconds, bool gpu) {
    RunConfig run;
    run.scene = scene;
    run.sets = {"ao.enabled=false", "shadows.enabled=false"};
    run.width = kW;
    run.height = kH;
    run.sceneTime = seconds;
    auto s = test::makeSession(kW, kH);
    s->pipeline().setGpuPosing(gpu);
    s->loadScene(scene, run);
    return s;
}

void expectGpuPoseEqualsCpuPose(const std::string& scene) {
    // GPU: uploaded at 0 s, moved to 0.5 s by the dispatch alone.
    auto gpu = sessionAt(scene, 0.0, true);
    ASSERT_TRUE(gpu->pipeline().gpuScene().posesOnGpu()) << scene;
    const GBuffer at0 = read(*gpu);
    gpu->setSceneTime(0.5);
    const GBuffer gpu05 = read(*gpu);
    EXPECT_GT(gpu->pipeline().gpuScene().lastPoseUploadBytes(), 0u);
    // CPU: poseScene's vertices uploaded.
    auto cpu = sessionAt(scene, 0.0, false);
    ASSERT_FALSE(cpu->pipeline().gpuScene().posesOnGpu());
    cpu->setSceneTime(0.5);
    const GBuffer cpu05 = read(*cpu);

    const Difference pos = compare(gpu05.position, cpu05.position);
    const Difference moved = compare(gpu05.position, at0.position);
    double normals = 0.0;  // the encoded normals' largest difference
    for (std::size_t i = 0; i < gpu05.normal.pixels.size(); ++i)
        normals = std::max(normals, static_cast<double>(std::abs(gpu05.normal.pixels[i] - cpu05.normal.pixels[i])));
    std::printf("%s: GPU vs CPU pose at 0.5 s: view position max %.3g, encoded normal max %.3g, coverage differs in %d "
                "pixels; 0.5 s vs 0 s: %d pixels changed\n",
                scene.c_str(), pos.max, normals, pos.coverageDiffers, moved.changed);
    EXPECT_LT(pos.max, 1e-4) << scene;               // float rounding of positions a few units from the camera
    EXPECT_LE(pos.coverageDiffers, 2) << scene;      // an edge pixel may flip on rounding
    EXPECT_LT(normals, 2e-3) << scene;               // the encoded normal's quantisation step
    EXPECT_GT(moved.changed, kW * kH / 100) << scene;  // and it moved: over 1% of the pixels changed
}

TEST(GpuSkinning, TheComputePoseMatchesTheCpuPoseOnTheTestsGltf) {
    expectGpuPoseEqualsCpuPose(test::writeJson("gpu-skinning.gltf", test::animatedGltf()).string());
}

TEST(GpuSkinning, TheComputePoseMatchesTheCpuPoseOnTheAssimpSkinAndMorphSamples) {
    const std::string dir = "/usr/share/assimp/models/glTF2/";
    for (const char* file : {"simple_skin/simple_skin.gltf", "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf"}) {
        if (!std::filesystem::exists(dir + file)) GTEST_SKIP() << "assimp-testmodels is not installed";
        expectGpuPoseEqualsCpuPose(dir + file);
    }
}

// The cost of one pose on a 40 000-vertex skinned and morphed grid, each way:
// poseScene (the CPU pose: nodes, joint matrices, and every vertex, which the
// reference, the bounds and records read) and then the GPU's copy written,
// either the posed vertices uploaded (72 bytes a vertex) or the joint
// matrices and morph weights uploaded and the dispatch run (glFinish'd).
// Prints the medians (docs/scene-format.md, "Animation"); asserts the two
// ways' G-buffers agree on this grid too.
TEST(GpuSkinning, PrintsThePerPoseCostOfEachWayOnAGrid) {
    const std::string scene = test::writeJson("gpu-skinning-grid.gltf", skinnedGrid(200)).string();
    expectGpuPoseEqualsCpuPose(scene);
    for (bool gpu : {false, true}) {
        auto s = sessionAt(scene, 0.0, gpu);
        std::vector<double> pose, write;
        for (int k = 1; k <= 21; ++k) {
            const auto t0 = std::chrono::steady_clock::now();
            poseScene(s->mutableScene(), 0.04 * k);
            const auto t1 = std::chrono::steady_clock::now();
            s->pipeline().updatePose(s->scene());
            glFinish();
            const auto t2 = std::chrono::steady_clock::now();
            pose.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
            write.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
        }
        std::sort(pose.begin(), pose.end());
        std::sort(write.begin(), write.end());
        std::printf("grid 200x200 (40000 vertices), %s: poseScene (CPU) median %.2f ms [%.2f, %.2f], then %s median "
                    "%.2f ms [%.2f, %.2f], %zu bytes uploaded a pose (21 poses; [min, max])\n",
                    gpu ? "GPU posing" : "CPU posing", pose[10], pose.front(), pose.back(),
                    gpu ? "joint matrices + weights uploaded and the dispatch" : "the vertices uploaded", write[10],
                    write.front(), write.back(), s->pipeline().gpuScene().lastPoseUploadBytes());
        EXPECT_EQ(s->pipeline().gpuScene().lastPoseUploadBytes(), gpu ? 2 * 64 + 4 : 40000 * 72u);
    }
}

}  // namespace
}  // namespace dw
