// One ray scene per scene (issue 33, "a scene read once"): every camera and
// sweep point of a run traces the same RayScene, built once relative to the
// scene's centre; its images agree with the per-camera frame every reference
// used before (RayScene built at the camera's position) within the bound
// docs/reference.md states; a tradeoff over an orbit of cameras builds one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/RunConfig.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/reference/RayScene.h"
#include "renderer/reference/RaySceneCache.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/scene/CameraPath.h"
#include "renderer/scene/SceneLoader.h"
#include "renderer/study/TradeoffStudy.h"
#include "tests/support/TestSupport.h"

namespace dw {
namespace {

namespace fs = std::filesystem;

// Shadows and 16 AO rays with a radius of a fifth of the scene's size: every
// kind of ray the reference casts.
reference::ReferenceModel fullModel(const Scene& scene) {
    reference::ReferenceModel m;
    m.shadows = true;
    m.rayTracedAo = true;
    m.aoRays = 16;
    m.aoRadius = 0.2 * std::max(static_cast<double>(scene.bounds().radius()), 1e-3);
    return m;
}

std::vector<Camera> orbit(const Scene& scene, int n) {
    const CameraPath path = CameraPath::orbit(scene.camera, n);
    std::vector<Camera> cameras;
    for (int k = 0; k < n; ++k) cameras.push_back(path.at(k, n));
    return cameras;
}

reference::ReferenceRequest request(const Camera& c, int w, int h) {
    reference::ReferenceRequest r;
    r.camera = c;
    r.width = w;
    r.height = h;
    return r;
}

bool sameBytes(const FloatImage& a, const FloatImage& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::equal(a.pixels.begin(), a.pixels.end(), b.pixels.begin(), [](float x, float y) {
               return std::memcmp(&x, &y, sizeof x) == 0;
           });
}

// The shared frame's image against the per-camera frame's: the share of
// pixels whose L-buffer luminance differs by more than 1e-5 relative (a ray
// that met another triangle at an edge, a shadow ray that grazed one), and
// the AO's largest and mean difference in units of the AO estimate's mean
// standard error (the reference's own error).
struct FrameDifference {
    double lbufferPixels = 0.0, aoMax = 0.0, aoMean = 0.0;
};
FrameDifference difference(const reference::ReferenceImages& shared, const reference::ReferenceImages& perCamera) {
    FrameDifference d;
    const size_t n = shared.ao.pixels.size();
    long long differing = 0;
    double aoSum = 0.0;
    for (size_t p = 0; p < n; ++p) {
        const float* a = &shared.lbuffer.pixels[p * 4];
        const float* b = &perCamera.lbuffer.pixels[p * 4];
        const double la = reference::luminance(a[0], a[1], a[2]), lb = reference::luminance(b[0], b[1], b[2]);
        if (std::abs(la - lb) > 1e-5 * std::max(std::abs(lb), 1e-3)) ++differing;
        const double ao = std::abs(static_cast<double>(shared.ao.pixels[p]) - perCamera.ao.pixels[p]);
        d.aoMax = std::max(d.aoMax, ao);
        aoSum += ao;
    }
    const double sigma = std::max(perCamera.stats.aoStandardErrorMean, 1e-12);
    d.lbufferPixels = static_cast<double>(differing) / static_cast<double>(n);
    d.aoMax /= sigma;
    d.aoMean = aoSum / static_cast<double>(n) / sigma;
    return d;
}

// Each camera of an orbit traced on the shared ray scene and on its own
// per-camera one; the largest differences over the cameras.
FrameDifference worstOverOrbit(const Scene& scene, int cameras, int w, int h) {
    const reference::ReferenceModel model = fullModel(scene);
    reference::RaySceneCache shared;
    FrameDifference worst;
    for (const Camera& c : orbit(scene, cameras)) {
        const reference::ReferenceImages a = reference::renderReference(scene, model, request(c, w, h), nullptr, &shared);
        const reference::RayScene own(scene, glm::dvec3(c.position));
        const reference::ReferenceImages b = reference::renderReference(scene, own, model, request(c, w, h));
        const FrameDifference d = difference(a, b);
        worst.lbufferPixels = std::max(worst.lbufferPixels, d.lbufferPixels);
        worst.aoMax = std::max(worst.aoMax, d.aoMax);
        worst.aoMean = std::max(worst.aoMean, d.aoMean);
    }
    std::printf("shared vs per-camera frame: %.4f%% of pixels differ in L, AO max %.3f sigma, mean %.5f sigma\n",
                100.0 * worst.lbufferPixels, worst.aoMax, worst.aoMean);
    return worst;
}

TEST(RaySceneShare, EightCamerasOfAnOrbitShareOneBuild) {
    const Scene scene = loadScene("default");
    const reference::ReferenceModel model = fullModel(scene);
    reference::RaySceneCache shared;
    const long long before = reference::RayScene::buildCount();
    std::vector<reference::ReferenceImages> images;
    for (const Camera& c : orbit(scene, 8))
        images.push_back(reference::renderReference(scene, model, request(c, 32, 18), nullptr, &shared));
    EXPECT_EQ(reference::RayScene::buildCount() - before, 1);
    // The same images as a ray scene built for each render alone (the same frame: the scene's centre).
    const Camera last = orbit(scene, 8).back();
    const reference::ReferenceImages alone = reference::renderReference(scene, model, request(last, 32, 18));
    EXPECT_EQ(reference::RayScene::buildCount() - before, 2);
    EXPECT_TRUE(sameBytes(alone.lbuffer, images.back().lbuffer));
    EXPECT_TRUE(sameBytes(alone.ao, images.back().ao));
    EXPECT_TRUE(sameBytes(alone.shadow, images.back().shadow));
}

TEST(RaySceneShare, ASceneOfOtherContentIsBuiltAgainAndOutlivesItsScene) {
    reference::RaySceneCache shared;
    const long long before = reference::RayScene::buildCount();
    std::shared_ptr<const reference::RayScene> first;
    {
        const Scene a = loadScene("default");
        first = shared.get(a);
        const Scene copy = a;  // another object, the same content: the same ray scene
        EXPECT_EQ(shared.get(copy), first);
    }
    EXPECT_EQ(reference::RayScene::buildCount() - before, 1);
    Scene moved = loadScene("default");
    moved.instances.front().transform[3][0] += 1.0f;  // geometry changed: a new build
    EXPECT_NE(shared.get(moved), first);
    EXPECT_EQ(reference::RayScene::buildCount() - before, 2);
    // The first one, its scene gone, still answers (it keeps what its queries read).
    const reference::RayHit hit = first->intersect(glm::dvec3(0.0, 50.0, 0.0) - first->origin(),
                                                   glm::dvec3(0.0, -1.0, 0.0), 0.0, 1e9,
                                                   reference::Visibility::Camera);
    EXPECT_TRUE(hit.hit);
}

// The bounds docs/reference.md states ("One ray scene per scene").
TEST(RaySceneShare, TheSharedFrameAgreesWithThePerCameraFrameOnABuiltInScene) {
    const FrameDifference d = worstOverOrbit(loadScene("default"), 4, 80, 45);
    EXPECT_LE(d.lbufferPixels, 0.01);
    EXPECT_LE(d.aoMean, 0.05);
}

TEST(RaySceneShare, TheSharedFrameAgreesWithThePerCameraFrameOnAGltf) {
    const FrameDifference d = worstOverOrbit(loadScene(DW_TEST_GLTF_DIR "/split_corner_tangents.gltf"), 4, 80, 45);
    EXPECT_LE(d.lbufferPixels, 0.01);
    EXPECT_LE(d.aoMean, 0.05);
}

// tradeoff --orbit 3 in process: three references (no cache), one ray scene.
TEST(RaySceneShare, ATradeoffOverThreeCamerasBuildsOneRayScene) {
    const fs::path cache = test::tempDir() / "rayscene-share-cache";
    fs::remove_all(cache);
    ::setenv("DW_REFERENCE_CACHE", cache.c_str(), 1);
    TradeoffStudyOptions o;
    o.run.scene = "default";
    o.run.width = 32;
    o.run.height = 18;
    o.sweep = {BenchGrid::parseSweep("shadows.map_size=256,512")};
    o.aoRays = 4;
    o.orbit = 3;
    o.frames = 1;
    o.warmup = 0;
    o.resamples = 100;
    TradeoffRunner runner(TradeoffStudy::runnerOptions(o));
    const long long before = reference::RayScene::buildCount();
    const TradeoffMeasurement m = TradeoffStudy::measure(runner, o.aoRays, "test", {}, 1);
    ::unsetenv("DW_REFERENCE_CACHE");
    fs::remove_all(cache);
    EXPECT_EQ(reference::RayScene::buildCount() - before, 1);
    bool three = false;
    for (const auto& [name, value] : m.result.settings)
        if (name == "references_rendered") three = value == "3";
    EXPECT_TRUE(three);
}

}  // namespace
}  // namespace dw
