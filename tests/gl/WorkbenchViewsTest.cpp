// The renderer pieces the workbench window shows: the pixel probe, the
// light-overlap cost map, the volume wireframe overlay and the forward modes.
#include <gtest/gtest.h>

#include "renderer/inspect/ForwardPreview.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/inspect/PixelProbe.h"
#include "renderer/inspect/ViewportOverlay.h"
#include "renderer/passes/LightingPass.h"
#include "tests/support/TestSupport.h"

using namespace dw;

TEST(PixelProbe, DecodesTheGBufferLikeTheDecodePass) {
    auto s = test::makeSession(96, 54);
    s->loadScene("spheres");
    s->render({{"final", "gbuffer.view_position", "gbuffer.view_normal"}});
    const FloatImage P = s->readRaw("gbuffer.view_position");
    const FloatImage N = s->readRaw("gbuffer.view_normal");
    const FloatImage L = s->readRaw("lbuffer");
    int surfaces = 0;
    for (int y = 3; y < 54; y += 10)
        for (int x = 5; x < 96; x += 11) {
            const ProbeResult r = probePixel(s->pipeline(), x, y);
            ASSERT_TRUE(r.inside);
            EXPECT_EQ(r.surface.background, P.at(x, y, 3) == 0.0f);
            if (r.surface.background) continue;
            ++surfaces;
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(r.surface.viewPosition[c], P.at(x, y, c), 1e-3f * std::max(1.0f, std::fabs(P.at(x, y, c))));
                EXPECT_NEAR(r.surface.viewNormal[c], N.at(x, y, c), 1e-4f);
                EXPECT_FLOAT_EQ(r.surface.radiance[c], L.at(x, y, c));
            }
            EXPECT_NEAR(r.surface.linearDepth, -P.at(x, y, 2), 1e-3f * std::fabs(P.at(x, y, 2)));
        }
    EXPECT_GT(surfaces, 10);
    // Every produced output has a value there, the 1x1 statistics included.
    const ProbeResult r = probePixel(s->pipeline(), 10, 10);
    std::vector<std::string> names;
    for (const auto& v : r.values) names.push_back(v.output);
    for (const char* n : {"gbuffer.albedo", "gbuffer.depth", "lbuffer", "luminance.stats", "final"})
        EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
    EXPECT_FALSE(probePixel(s->pipeline(), 96, 0).inside);
}

TEST(LightOverlap, CountsLightShaderInvocationsPerPixel) {
    auto s = test::makeSession(96, 54);
    s->loadScene("default");
    const int lights = s->scene().countLights(LightType::Point) + s->scene().countLights(LightType::Spot) +
                       s->scene().countLights(LightType::Directional);
    s->knobs().setFromString("lighting.strategy", "fullscreen");
    s->render({{"lighting.overlap"}});
    const auto brute = test::stats(s->readRaw("lighting.overlap"), 0);
    // Brute force runs every light on every pixel.
    EXPECT_EQ(brute.min, lights);
    EXPECT_EQ(brute.max, lights);
    s->knobs().setFromString("lighting.strategy", "stencil_volumes");
    s->render({{"lighting.overlap"}});
    const auto stencil = test::stats(s->readRaw("lighting.overlap"), 0);
    EXPECT_GE(stencil.min, s->scene().countLights(LightType::Directional));
    EXPECT_LT(stencil.mean, brute.mean * 0.8);
    s->knobs().setFromString("lighting.strategy", "volumes");
    s->render({{"lighting.overlap"}});
    EXPECT_GE(test::stats(s->readRaw("lighting.overlap"), 0).mean, stencil.mean);
    // Not asked for: the lighting pass skips the count, and says it did not write it.
    EXPECT_TRUE(s->render().find("lighting")->ran);
    EXPECT_FALSE(s->pipeline().outputs().find("lighting.overlap")->producedThisFrame);
    EXPECT_TRUE(s->pipeline().outputs().find("lbuffer")->producedThisFrame);
}

TEST(ViewportOverlay, DrawsVolumesAndAxesOverTheImage) {
    auto s = test::makeSession(128, 72);
    Scene scene = test::planeScene();
    test::addPointLight(scene, {0.0f, 1.0f, 0.0f}, glm::vec3(1.0f, 0.2f, 0.2f), {1.0f, 0.0f, 1.0f});
    s->setScene(std::move(scene));
    s->render();
    ViewportOverlay overlay;
    overlay.setup(s->shaders());
    const PublishedOutput* final = s->pipeline().outputs().find("final");
    const FloatImage base = readRgba8(*final->texture);
    OverlaySettings none;
    const FloatImage same = readRgba8(overlay.compose(*final->texture, nullptr, s->scene(), s->pipeline().lastCamera(), none));
    EXPECT_EQ(test::maxAbsDifference(base, same, 3), 0.0);
    OverlaySettings on;
    on.lightVolumes = true;
    on.axes = true;
    const FloatImage drawn = readRgba8(overlay.compose(*final->texture, s->pipeline().outputs().find("gbuffer.depth")->texture,
                                                       s->scene(), s->pipeline().lastCamera(), on));
    int changed = 0, reddish = 0;
    for (int y = 0; y < drawn.height; ++y)
        for (int x = 0; x < drawn.width; ++x) {
            if (std::fabs(drawn.at(x, y, 0) - base.at(x, y, 0)) + std::fabs(drawn.at(x, y, 1) - base.at(x, y, 1)) > 0.05f) ++changed;
            if (drawn.at(x, y, 0) > drawn.at(x, y, 1) + 0.2f) ++reddish;
        }
    EXPECT_GT(changed, 100);  // wireframe lines and axes
    EXPECT_GT(reddish, 20);   // the light's colour
}

TEST(ForwardPreview, TexturedAndWireframeModesDrawTheScene) {
    auto s = test::makeSession(96, 54);
    s->loadScene("spheres");
    s->render();
    ForwardPreview preview;
    preview.setup(s->shaders());
    const auto textured = test::stats(readRgba8(preview.render(s->pipeline().gpuScene(), 96, 54, ForwardPreview::Mode::Textured)), 0);
    const auto wire = test::stats(readRgba8(preview.render(s->pipeline().gpuScene(), 96, 54, ForwardPreview::Mode::Wireframe)), 0);
    EXPECT_GT(textured.max - textured.min, 0.3);
    EXPECT_GT(wire.max - wire.min, 0.3);
    EXPECT_LT(wire.mean, textured.mean);  // lines on black
}
