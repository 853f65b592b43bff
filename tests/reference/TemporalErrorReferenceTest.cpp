// Issue 35 part 4 on the GPU: the temporal error (renderer/metrics/
// TemporalError.h) of rendered sequences against the CPU reference's. A still
// camera on a static scene changes nothing, on either side: 0 for the pixel
// centres (aa.method=none) and for FXAA. A camera sliding sideways by a
// quarter of a pixel per frame makes the pixel centres' edges stand still and
// jump (flicker) where the reference's area means move smoothly; TAA,
// rendered in order so its history follows the camera, flickers less.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "renderer/RunConfig.h"
#include "renderer/metrics/TemporalError.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "tests/support/TestSupport.h"

namespace dw {
namespace {

constexpr int kW = 48, kH = 27;

// Everything but the pixel's area at its most accurate (ReferenceGpuAgreementTest's
// list), and no effect the reference lacks (bloom; auto exposure, which would
// also change the image from frame to frame by itself).
const std::vector<std::string> kSets = {"lighting.strategy=fullscreen", "lighting.threshold=1e-5", "ao.enabled=false",
                                        "gbuffer.material_format=unorm16", "gbuffer.texture_filter=base_level",
                                        "shadows.enabled=false", "bloom.enabled=false", "tonemap.auto_exposure=false"};

std::unique_ptr<RenderSession> session(const std::string& method) {
    RunConfig run;
    run.scene = "default";
    run.sets = kSets;
    run.width = kW;
    run.height = kH;
    auto s = test::makeSession(kW, kH);
    s->loadScene("default", run);
    s->knobs().setFromString("aa.method", method);
    return s;
}

// The frames of `path` rendered in order by one session (TAA's history is
// carried from each frame to the next), after `settle` frames at path[0].
std::vector<FloatImage> renderSequence(const std::string& method, const std::vector<Camera>& path, int settle) {
    auto s = session(method);
    std::vector<FloatImage> frames;
    s->camera() = path.front();
    for (int i = 0; i < settle; ++i) s->render();
    for (const Camera& c : path) {
        s->camera() = c;
        s->render();
        frames.push_back(s->readRaw("final"));
    }
    return frames;
}

// The reference's final image of each camera, `spp` samples a pixel.
std::vector<FloatImage> referenceSequence(const std::vector<Camera>& path, int spp) {
    auto s = session("none");
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(s->knobs(), s->scene());
    model.pixelSamples = spp;
    std::vector<FloatImage> frames;
    for (const Camera& c : path) {
        reference::ReferenceRequest r;
        r.camera = c;
        r.width = kW;
        r.height = kH;
        frames.push_back(reference::renderReference(s->scene(), model, r).final);
    }
    return frames;
}

// The scene's camera moved sideways `frames` times by `pixels` of the image
// at the target's distance each time.
std::vector<Camera> slide(int frames, double pixels) {
    const Camera start = session("none")->camera();
    const glm::vec3 forward = start.target - start.position;
    const glm::vec3 right = glm::normalize(glm::cross(forward, start.up));
    const double pixel = 2.0 * glm::length(forward) * std::tan(glm::radians(start.fovYDegrees) / 2.0) / kH;
    std::vector<Camera> path;
    for (int i = 0; i < frames; ++i) {
        Camera c = start;
        const glm::vec3 move = right * static_cast<float>(pixels * pixel * i);
        c.position += move;
        c.target += move;
        path.push_back(c);
    }
    return path;
}

}  // namespace

TEST(TemporalErrorAgainstReference, AStillCameraOnAStaticSceneHasNone) {
    const std::vector<Camera> still = slide(3, 0.0);
    const std::vector<FloatImage> ref = referenceSequence(still, 1);
    for (const char* method : {"none", "fxaa"}) {
        const TemporalErrorResult r = TemporalError::measure(ref, renderSequence(method, still, 1));
        EXPECT_EQ(r.mean, 0.0) << method;
        EXPECT_EQ(r.interval.high, 0.0) << method;
    }
}

TEST(TemporalErrorAgainstReference, ASubPixelCameraMoveFlickersMoreWithoutAntialiasingThanWithTaa) {
    const std::vector<Camera> path = slide(9, 0.25);
    const std::vector<FloatImage> ref = referenceSequence(path, 16);
    const TemporalErrorResult none = TemporalError::measure(ref, renderSequence("none", path, 1));
    const TemporalErrorResult taa = TemporalError::measure(ref, renderSequence("taa", path, 32));
    std::printf("default %dx%d, camera sliding 0.25 px a frame, 8 frame pairs, against the reference at 16 spp: "
                "temporal error none %.5f [%.5f, %.5f], taa %.5f [%.5f, %.5f]\n",
                kW, kH, none.mean, none.interval.low, none.interval.high, taa.mean, taa.interval.low,
                taa.interval.high);
    EXPECT_GT(none.mean, 0.0);
    EXPECT_LT(taa.mean, none.mean);
    EXPECT_LT(taa.interval.high, none.interval.low);  // apart beyond their intervals
}

}  // namespace dw
