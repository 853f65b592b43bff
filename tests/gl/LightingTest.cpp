// The L-buffer: the stencil-routed light volumes give the same image as
// evaluating every light over every pixel (seed 000 section 6.1: identical up
// to rounding), and both match the CPU double-precision shading equation.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/lighting/LightVolume.h"
#include "renderer/passes/LightingPass.h"
#include "renderer/reference/ShadingReference.h"
#include "renderer/scene/BuiltinScenes.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

constexpr int W = 160, H = 90;

FloatImage lbufferWith(RenderSession& s, const std::string& strategy, const std::string& count = "depth_fail") {
    s.knobs().setFromString("lighting.strategy", strategy);
    s.knobs().setFromString("lighting.stencil_count", count);
    s.render({{"lbuffer"}});
    return s.readRaw("lbuffer");
}

// |a - b| relative to the larger value, for RGBA16F sums added in different orders.
double worstRelative(const FloatImage& a, const FloatImage& b, int* wx = nullptr, int* wy = nullptr) {
    double worst = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double va = a.at(x, y, c), vb = b.at(x, y, c);
                const double d = std::fabs(va - vb) / (std::max(std::fabs(va), std::fabs(vb)) + 1e-3);
                if (d > worst) {
                    worst = d;
                    if (wx) *wx = x;
                    if (wy) *wy = y;
                }
            }
    return worst;
}

}  // namespace

TEST(Lighting, StencilVolumesEqualBruteForceOnTheDefaultScene) {
    auto session = test::makeSession(W, H);
    session->loadScene("default");
    const auto* lighting = session->pipeline().pass<LightingPass>();
    const FloatImage brute = lbufferWith(*session, "fullscreen");
    EXPECT_EQ(lighting->lastCounts().volumes, 0);
    EXPECT_GT(lighting->lastCounts().fullscreen, 30);
    const FloatImage stencil = lbufferWith(*session, "stencil_volumes");
    const FloatImage volumes = lbufferWith(*session, "volumes");
    int x = 0, y = 0;
    const double dStencil = worstRelative(stencil, brute, &x, &y);
    std::printf("stencil vs brute force: worst relative difference %.2g at (%d, %d)\n", dStencil, x, y);
    EXPECT_LT(dStencil, 5e-3) << "at " << x << "," << y;
    EXPECT_LT(worstRelative(volumes, brute), 5e-3);
    // The light volumes did the work instead of full-screen passes.
    EXPECT_GT(lighting->lastCounts().volumes, 10);
}

TEST(Lighting, StencilVolumesEqualBruteForceWithTheCameraInsideVolumes) {
    auto session = test::makeSession(W, H);
    session->setScene(test::boxesScene(true));
    // Stand among the lights: the camera is inside several spheres and cones.
    session->camera().position = {0.0f, 1.0f, 3.5f};
    session->camera().target = {0.0f, 0.5f, -2.0f};
    const FloatImage brute = lbufferWith(*session, "fullscreen");
    const FloatImage depthFail = lbufferWith(*session, "stencil_volumes", "depth_fail");
    EXPECT_LT(worstRelative(depthFail, brute), 5e-3);
    // Seed 001's depth-pass count loses the lights around the camera.
    const FloatImage depthPass = lbufferWith(*session, "stencil_volumes", "depth_pass");
    EXPECT_GT(worstRelative(depthPass, brute), 0.1);
}

TEST(Lighting, LBufferMatchesTheCpuShadingEquation) {
    auto session = test::makeSession(W, H);
    Scene s = test::boxesScene(true);
    s.ambient = glm::vec3(0.0f);
    const std::vector<Light> lights = s.lights;
    session->setScene(std::move(s));
    for (const char* attenuation : {"classic", "windowed"}) {
        session->knobs().setFromString("lighting.attenuation", attenuation);
        session->render({{"lbuffer", "gbuffer.view_position", "gbuffer.view_normal"}});
        const FloatImage L = session->readRaw("lbuffer");
        const test::GBufferImages g = test::readGBuffer(*session);
        const glm::dmat4 view = session->pipeline().lastCamera().worldToView();  // the matrix the frame used
        const double threshold = session->knobs().value(*session->knobs().find("lighting.threshold"));
        const auto model = std::string(attenuation) == "windowed" ? reference::AttenuationModel::Windowed
                                                                  : reference::AttenuationModel::Classic;
        double worst = 0.0;
        int checked = 0;
        for (int y = 0; y < H; y += 3)
            for (int x = 0; x < W; x += 3) {
                if (!g.surface(x, y)) continue;
                const glm::dvec3 expected = test::referenceRadiance(lights, view, g.at(x, y), threshold, model);
                for (int c = 0; c < 3; ++c) {
                    const double got = L.at(x, y, c);
                    worst = std::max(worst, std::fabs(got - expected[c]) / (std::fabs(expected[c]) + 0.01));
                }
                ++checked;
            }
        std::printf("L-buffer vs CPU reference (%s): worst relative error %.3g over %d pixels\n", attenuation, worst, checked);
        EXPECT_GT(checked, 300);
        EXPECT_LT(worst, 1e-2) << attenuation;
    }
}

TEST(Lighting, LightStopsAtItsRadiusAndTheWindowFadesItToZero) {
    auto session = test::makeSession(W, H);
    Scene s = test::planeScene(60.0f);
    s.camera.position = {0.0f, 30.0f, 0.01f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.fovYDegrees = 70.0f;
    // High enough that N.L is about 0.7 where the sphere meets the floor.
    test::addPointLight(s, {0.0f, 15.0f, 0.0f}, glm::vec3(1.0f), {1.0f, 0.0f, 0.1f});
    session->setScene(std::move(s));
    session->knobs().setFromString("lighting.threshold", "0.02");
    const double r = solveLightRadius({1.0f, 0.0f, 0.1f}, 1.0, 0.02);
    for (const char* attenuation : {"classic", "windowed"}) {
        session->knobs().setFromString("lighting.attenuation", attenuation);
        session->render({{"lbuffer", "gbuffer.view_position"}});
        const FloatImage L = session->readRaw("lbuffer");
        const FloatImage P = session->readRaw("gbuffer.view_position");
        const glm::dvec3 lightView = glm::dvec3(glm::dmat4(session->camera().view()) * glm::dvec4(0.0, 15.0, 0.0, 1.0));
        double maxOutside = 0.0, maxNearEdge = 0.0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const double d = glm::length(glm::dvec3(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2)) - lightView);
                if (d > r * 1.001) maxOutside = std::max(maxOutside, static_cast<double>(L.at(x, y, 0)));
                if (d > r * 0.97 && d < r) maxNearEdge = std::max(maxNearEdge, static_cast<double>(L.at(x, y, 0)));
            }
        EXPECT_EQ(maxOutside, 0.0) << attenuation;
        if (std::string(attenuation) == "classic") {
            // Just inside the radius the contribution is about the threshold times N.L.
            EXPECT_GT(maxNearEdge, 0.02 * 0.5);
            EXPECT_LT(maxNearEdge, 0.02 * 1.1);
        } else {
            // Ferko's window (1 - (d/r)^20) has taken most of it away by then.
            EXPECT_LT(maxNearEdge, 0.02 * 0.5);
        }
    }
}

// lighting.batched_volumes: the volume strategies draw many lights per call
// (volumes: one draw; stencil_volumes: batches of lights
// whose screen rectangles are disjoint, renderer/lighting/ScreenBatches.h).
// The image is the one-light-at-a-time image up to the order of the additive
// sums; a batch that let two volumes share a pixel would lose a light there
// (the first shade zeroes the stencil), far beyond that bound. Depth-fail and
// depth-pass counting, 200 overlapping small lights, and the camera inside
// volumes (whose rectangles are the whole screen).
TEST(Lighting, BatchedVolumesEqualOneLightAtATime) {
    auto session = test::makeSession(96, 54);
    const auto* lighting = session->pipeline().pass<LightingPass>();
    auto lbuffer = [&](const std::string& strategy, const std::string& count, bool batched) {
        session->knobs().setFromString("lighting.batched_volumes", batched ? "true" : "false");
        return lbufferWith(*session, strategy, count);
    };
    struct Case {
        const char* what;
        Scene scene;
        glm::vec3 position{0.0f}, target{0.0f};
    };
    std::vector<Case> cases;
    cases.push_back({"200 small lights", test::straddleScene(3)});
    cases.push_back({"camera inside volumes", test::boxesScene(true), {0.0f, 1.0f, 3.5f}, {0.0f, 0.5f, -2.0f}});
    for (Case& c : cases) {
        session->setScene(std::move(c.scene));
        if (c.position != c.target) {
            session->camera().position = c.position;
            session->camera().target = c.target;
        }
        for (const char* strategy : {"stencil_volumes", "volumes"})
            for (const char* count : {"depth_fail", "depth_pass"}) {
                if (std::string(strategy) == "volumes" && std::string(count) == "depth_pass") continue;
                const FloatImage one = lbuffer(strategy, count, false);
                const int volumes = lighting->lastCounts().volumes;
                EXPECT_EQ(lighting->lastCounts().batches, 0);
                const FloatImage batched = lbuffer(strategy, count, true);
                const LightingPass::Counts counts = lighting->lastCounts();
                int x = 0, y = 0;
                const double d = worstRelative(batched, one, &x, &y);
                std::printf("%s, %s (%s): %d volumes in %d batches; worst relative difference to one light "
                            "at a time %.2g at (%d, %d)\n",
                            c.what, strategy, count, counts.volumes, counts.batches, d, x, y);
                EXPECT_LT(d, 1e-5) << c.what << ", " << strategy << " " << count << " at " << x << "," << y;
                EXPECT_EQ(counts.volumes, volumes) << c.what << ", " << strategy;
                EXPECT_GE(counts.batches, 1) << c.what << ", " << strategy;
                if (std::string(strategy) == "volumes") {
                    EXPECT_EQ(counts.batches, 1) << c.what;
                } else if (std::string(c.what) == "200 small lights") {
                    // (Inside or behind the camera, a volume's rectangle is the whole screen.)
                    EXPECT_LT(counts.batches, counts.volumes / 2) << c.what;
                }
            }
    }
}
