// SSAO (seed 000 4.6.3): no self-occlusion on an open plane, darker in a
// concave corner; the cross-bilateral blur (eq. 4.7) keeps occlusion from
// leaking across a depth step, which a plain gaussian does not.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/GpuScene.h"
#include "renderer/graph/ResourcePool.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/passes/AoFilterPass.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

Scene withAmbient(Scene s) {
    s.ambient = glm::vec3(0.2f);
    return s;
}

}  // namespace

TEST(Ssao, AnOpenFlatPlaneIsNotOccluded) {
    auto s = test::makeSession(160, 90);
    s->setScene(withAmbient(test::planeScene(200.0f)));
    for (const char* res : {"full", "half", "quarter"}) {
        s->knobs().setFromString("ssao.resolution", res);
        s->render({{"ao.raw", "gbuffer.depth"}});
        const FloatImage ao = s->readRaw("ao.raw");
        const auto st = test::stats(ao, 0);
        EXPECT_GT(st.mean, 0.995) << res;
        EXPECT_GT(st.min, 0.95) << res;
    }
}

TEST(Ssao, AConcaveCornerIsDarker) {
    auto s = test::makeSession(160, 90);
    Scene scene = withAmbient(test::planeScene(40.0f));
    // A wall along x = 0 standing on the floor: the crease at its foot is concave.
    Mesh wall = shapes::box({0.4f, 4.0f, 20.0f});
    wall.material = 0;
    scene.instances.push_back({scene.addMesh(std::move(wall)), glm::translate(glm::mat4(1.0f), {0.0f, 2.0f, 0.0f})});
    scene.camera.position = {5.0f, 3.0f, 6.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    s->setScene(std::move(scene));
    s->knobs().setFromString("ssao.resolution", "full");
    s->render({{"ao.raw", "gbuffer.view_position"}});
    const FloatImage ao = s->readRaw("ao.raw");
    const FloatImage P = s->readRaw("gbuffer.view_position");
    const glm::mat4 inverseView = glm::inverse(s->camera().view());
    double crease = 0, open = 0, near = 0, farther = 0;
    int nCrease = 0, nOpen = 0, nNear = 0, nFarther = 0;
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x) {
            if (P.at(x, y, 3) == 0.0f) continue;
            const glm::vec3 w(inverseView * glm::vec4(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2), 1.0f));
            if (w.y > 0.05f) continue;  // floor pixels only
            if (w.x > 0.2f && w.x < 0.6f) {
                crease += ao.at(x, y, 0);
                ++nCrease;
                if (w.x < 0.4f) {
                    near += ao.at(x, y, 0);
                    ++nNear;
                } else {
                    farther += ao.at(x, y, 0);
                    ++nFarther;
                }
            } else if (w.x > 3.0f) {
                open += ao.at(x, y, 0);
                ++nOpen;
            }
        }
    ASSERT_GT(nCrease, 10);
    ASSERT_GT(nOpen, 100);
    crease /= nCrease;
    open /= nOpen;
    std::printf("SSAO: floor at the wall's foot %.3f, open floor %.3f\n", crease, open);
    EXPECT_GT(open, 0.99);
    EXPECT_LT(crease, open - 0.08);
    // Darker the closer to the wall.
    ASSERT_GT(nNear, 3);
    ASSERT_GT(nFarther, 3);
    EXPECT_LT(near / nNear, farther / nFarther);
}

namespace {

// Runs AoFilterPass alone on a synthetic AO image and depth buffer: the left
// half near and occluded (AO 0.3), the right half far and open (AO 1).
FloatImage blurStep(const std::string& mode, int aoDivisor) {
    const int W = 128, H = 32;
    test::initGl();
    gl::ShaderLibrary shaders(gl::ShaderLibrary::locateRoot());
    KnobRegistry knobs;
    knobs.addBool("ao.enabled", true, "ao", "");
    AoFilterPass pass(knobs);
    knobs.setFromString("ssao_blur.mode", mode);
    knobs.setFromString("ssao_blur.width", "15");
    OutputRegistry outputs;
    outputs.declare("ao", {"ao.raw", OutputKind::Scalar, ""});
    outputs.declare("geometry", {"gbuffer.depth", OutputKind::Depth, ""});
    for (const auto& o : pass.outputs()) outputs.declare(pass.name(), o);
    pass.setup(shaders);
    pass.connect(knobs);
    ResourcePool pool;
    pool.acquireOutputs(pass, knobs, W, H, outputs);

    Camera cam;
    cam.nearPlane = 0.1f;
    cam.farPlane = 100.0f;
    const CameraUniforms cu = Pipeline::cameraUniforms(cam, W, H);
    auto windowDepth = [&](float z) {
        const glm::vec4 c = cu.projection * glm::vec4(0, 0, -z, 1);
        return c.z / c.w;  // clip depth is already in [0, 1]
    };
    std::vector<float> depth(W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) depth[y * W + x] = windowDepth(x < W / 2 ? 2.0f : 50.0f);
    gl::Texture depthTex = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, W, H);
    depthTex.upload(0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    const int aw = W / aoDivisor, ah = H / aoDivisor;
    std::vector<float> ao(aw * ah);
    for (int y = 0; y < ah; ++y)
        for (int x = 0; x < aw; ++x) ao[y * aw + x] = x < aw / 2 ? 0.3f : 1.0f;
    gl::Texture aoTex = gl::Texture::create2D(GL_R32F, aw, ah);
    aoTex.upload(0, aw, ah, GL_RED, GL_FLOAT, ao.data());
    outputs.bind("ao.raw", &aoTex, 1);
    outputs.bind("gbuffer.depth", &depthTex, 1);

    gl::Buffer camera = gl::Buffer::create(sizeof(CameraUniforms), &cu, false);
    camera.bindBase(GL_UNIFORM_BUFFER, binding::CAMERA_UBO);
    Scene scene;
    GpuScene gpu;
    FrameContext ctx{scene, gpu, knobs, outputs, shaders, cu, W, H, 0, {}, nullptr};
    gl::resetPipelineState(W, H);
    pass.execute(ctx);
    return readOutputRaw(*outputs.find("ao.filtered"));
}

// Smallest AO on the far (open) side, within 6 pixels of the depth step.
float leakBesideTheEdge(const FloatImage& img) {
    float worst = 1.0f;
    for (int y = 0; y < img.height; ++y)
        for (int x = img.width / 2; x < img.width / 2 + 6; ++x) worst = std::min(worst, img.at(x, y, 0));
    return worst;
}

}  // namespace

TEST(SsaoBlur, BilateralDoesNotLeakAcrossADepthStepButGaussianDoes) {
    for (int divisor : {1, 2}) {
        const FloatImage bilateral = blurStep("bilateral", divisor);
        const FloatImage gaussian = blurStep("gaussian", divisor);
        std::printf("AO beside the depth step (AO at 1/%d): bilateral %.3f, gaussian %.3f\n", divisor,
                    leakBesideTheEdge(bilateral), leakBesideTheEdge(gaussian));
        EXPECT_GT(leakBesideTheEdge(bilateral), 0.97f) << divisor;
        EXPECT_LT(leakBesideTheEdge(gaussian), 0.85f) << divisor;
        // The occluded side keeps its occlusion under the bilateral blur.
        EXPECT_NEAR(bilateral.at(bilateral.width / 2 - 3, 16, 0), 0.3f, 0.03f) << divisor;
    }
}
