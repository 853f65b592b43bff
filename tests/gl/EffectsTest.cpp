// The tunable effects of the pipeline (issue: SSAO, shadows, bloom, sky, DoF,
// FXAA): each does what its seed section says, and switching one off removes
// its pass.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/gl/DepthConvention.h"
#include "renderer/passes/LightingPass.h"
#include "renderer/passes/ShadowPass.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

constexpr int W = 160, H = 90;

// Pixel (x right, y down) where a world point lands.
glm::ivec2 project(RenderSession& s, const glm::vec3& p) {
    const glm::vec4 c(s.pipeline().lastCamera().worldToClip() * glm::dvec4(glm::dvec3(p), 1.0));
    const glm::vec2 ndc = glm::vec2(c) / c.w;
    return {static_cast<int>((ndc.x * 0.5f + 0.5f) * W), static_cast<int>((0.5f - ndc.y * 0.5f) * H)};
}

float red(const FloatImage& img, glm::ivec2 px) { return img.at(px.x, px.y, 0); }

// A floor, and a small box hovering over the origin.
Scene occluderScene() {
    Scene s = test::planeScene(40.0f);
    Mesh box = shapes::box({1.2f, 0.2f, 1.2f});
    box.material = 0;
    s.instances.push_back({s.addMesh(std::move(box)), glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 0.0f})});
    s.camera.position = {0.0f, 9.0f, 7.0f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    return s;
}

std::vector<std::string> ran(const FrameReport& r) {
    std::vector<std::string> names;
    for (const auto& p : r.passes)
        if (p.ran) names.push_back(p.name);
    return names;
}
bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

}  // namespace

TEST(Shadows, APointUnderTheOccluderIsShadowedAndOneBesideItIsNotForEveryLightType) {
    struct Case {
        const char* name;
        LightType type;
        const char* pointMethod;
    };
    for (const Case c : {Case{"directional", LightType::Directional, "cube"}, Case{"spot", LightType::Spot, "cube"},
                         Case{"point (cube)", LightType::Point, "cube"},
                         Case{"point (dual paraboloid)", LightType::Point, "dual_paraboloid"}}) {
        for (const char* reuse : {"true", "false"}) {
            auto s = test::makeSession(W, H);
            Scene scene = occluderScene();
            Light l;
            l.type = c.type;
            l.position = {0.0f, 4.0f, 0.0f};
            l.direction = {0.0f, -1.0f, 0.0f};
            l.cutoffDegrees = 50.0f;
            l.intensity = glm::vec3(1.0f);
            l.attenuation = {1.0f, 0.0f, 0.02f};
            l.castShadows = true;
            scene.lights.push_back(l);
            s->setScene(std::move(scene));
            s->knobs().setFromString("shadows.point_method", c.pointMethod);
            s->knobs().setFromString("shadows.reuse_map", reuse);
            s->render({{"lbuffer"}});
            const FloatImage L = s->readRaw("lbuffer");
            const float under = red(L, project(*s, {0.0f, 0.0f, 0.0f}));
            const float beside = red(L, project(*s, {2.6f, 0.0f, 0.0f}));
            EXPECT_GT(beside, 0.2f) << c.name;
            EXPECT_LT(under, beside * 0.05f) << c.name << " reuse " << reuse;
            EXPECT_EQ(s->pipeline().pass<LightingPass>()->lastCounts().shadowed, 1) << c.name;
        }
    }
}

// An occluder off every axis: a map drawn or read mirrored or rotated (a
// cube face's orientation, a paraboloid's handedness, a flipped light matrix)
// puts the shadow in one of the mirror positions instead.
TEST(Shadows, AnOffAxisOccludersShadowLandsWhereTheLightProjectsIt) {
    struct Case {
        const char* name;
        LightType type;
        const char* pointMethod;
        float cutoff;
        const char* distance = "0";  // directional: 0 fits the scene; 14 a sphere around the near frustum
    };
    const glm::vec3 lightPos(0.0f, 4.0f, 0.0f), box(1.5f, 1.0f, -1.0f);
    const glm::vec3 sunDir = glm::normalize(glm::vec3(0.5f, -1.0f, 0.3f));
    for (const Case c : {Case{"directional", LightType::Directional, "cube", 0.0f},
                         Case{"directional (frustum slice)", LightType::Directional, "cube", 0.0f, "14"},
                         Case{"spot", LightType::Spot, "cube", 50.0f},
                         Case{"wide spot (cube)", LightType::Spot, "cube", 75.0f},
                         Case{"point (cube)", LightType::Point, "cube", 0.0f},
                         Case{"point (dual paraboloid)", LightType::Point, "dual_paraboloid", 0.0f}}) {
        auto s = test::makeSession(W, H);
        Scene scene = test::planeScene(40.0f);
        Mesh m = shapes::box({0.6f, 0.2f, 0.6f});
        m.material = 0;
        scene.instances.push_back({scene.addMesh(std::move(m)), glm::translate(glm::mat4(1.0f), box)});
        scene.camera.position = {0.0f, 9.0f, 7.0f};
        scene.camera.target = {0.0f, 0.0f, 0.0f};
        Light l;
        l.type = c.type;
        l.position = lightPos;
        l.direction = c.type == LightType::Directional ? sunDir : glm::vec3(0.0f, -1.0f, 0.0f);
        l.cutoffDegrees = c.cutoff > 0.0f ? c.cutoff : 45.0f;
        l.intensity = glm::vec3(1.0f);
        l.attenuation = {1.0f, 0.0f, 0.02f};
        l.castShadows = true;
        scene.lights.push_back(l);
        s->setScene(std::move(scene));
        s->knobs().setFromString("shadows.point_method", c.pointMethod);
        s->knobs().setFromString("shadows.distance", c.distance);
        s->render({{"lbuffer"}});
        const FloatImage L = s->readRaw("lbuffer");
        // Where the box's centre falls on the floor, seen from the light.
        glm::vec3 shadow;
        if (c.type == LightType::Directional) shadow = box + sunDir * (box.y / -sunDir.y);
        else shadow = lightPos + (box - lightPos) * (lightPos.y / (lightPos.y - box.y));
        shadow.y = 0.0f;
        const float at = red(L, project(*s, shadow));
        for (const glm::vec3 mirror : {glm::vec3(-shadow.x, 0, shadow.z), glm::vec3(shadow.x, 0, -shadow.z),
                                       glm::vec3(-shadow.x, 0, -shadow.z), glm::vec3(shadow.z, 0, shadow.x)}) {
            const float lit = red(L, project(*s, mirror));
            EXPECT_GT(lit, 0.1f) << c.name << " at mirror (" << mirror.x << ", " << mirror.z << ")";
            EXPECT_LT(at, lit * 0.05f) << c.name << ": shadow expected at (" << shadow.x << ", " << shadow.z << ")";
        }
    }
}

// The shadow map's depth range follows the scene, not only the light's
// radius: a very bright light (radius in the thousands) and a scene at a
// hundredth of the scale both keep the shadow of a caster close to the light.
TEST(Shadows, CastersCloseToBrightLightsAndInTinyScenesStillShadow) {
    for (const float scale : {1.0f, 0.01f}) {
        for (const char* method : {"cube", "dual_paraboloid"}) {
            auto s = test::makeSession(W, H);
            Scene scene = test::planeScene(40.0f * scale);
            Mesh m = shapes::box(glm::vec3(1.2f, 0.2f, 1.2f) * scale);
            m.material = 0;
            scene.instances.push_back({scene.addMesh(std::move(m)), glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 0) * scale)});
            scene.camera.position = glm::vec3(0.0f, 9.0f, 7.0f) * scale;
            scene.camera.target = glm::vec3(0.0f);
            scene.camera.nearPlane = 0.05f * scale;
            scene.camera.farPlane = 100.0f * scale;
            Light l;
            l.type = LightType::Point;
            l.position = glm::vec3(0.0f, 1.5f, 0.0f) * scale;  // 0.4 above the box's top
            l.direction = {0.0f, -1.0f, 0.0f};
            l.intensity = glm::vec3(20000.0f);
            l.attenuation = {1.0f, 0.0f, 1.0f / (scale * scale)};
            l.castShadows = true;
            scene.lights.push_back(l);
            s->setScene(std::move(scene));
            s->knobs().setFromString("shadows.point_method", method);
            s->render({{"lbuffer"}});
            const FloatImage L = s->readRaw("lbuffer");
            const float under = red(L, project(*s, glm::vec3(0.0f)));
            const float beside = red(L, project(*s, glm::vec3(3.0f, 0.0f, 0.0f) * scale));
            EXPECT_GT(beside, 1.0f) << method << " scale " << scale;
            EXPECT_LT(under, beside * 0.05f) << method << " scale " << scale;
        }
    }
}

class ShadowAcne : public ::testing::TestWithParam<glm::vec3> {};

// At a grazing angle the slope-scaled offset matters; straight down (no
// slope) only the constant bias can cover the depth reconstruction error.
TEST_P(ShadowAcne, BiasRemovesAcneOnAnUnoccludedPlane) {
    auto s = test::makeSession(W, H);
    Scene scene = test::planeScene(40.0f);
    // A tall post behind the camera, its shadow falling off the plane, gives
    // the map a depth range of 30 units as a real scene would: the map is
    // fitted to the scene's bounds, and a lone plane's zero-depth box would
    // need no bias at all.
    Mesh post = shapes::box({0.5f, 30.0f, 0.5f});
    post.material = 0;
    scene.instances.push_back({scene.addMesh(std::move(post)), glm::translate(glm::mat4(1.0f), {18.0f, 15.0f, 18.0f})});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(GetParam());
    sun.intensity = glm::vec3(1.0f);
    sun.castShadows = true;
    scene.lights.push_back(sun);
    s->setScene(std::move(scene));
    s->knobs().setFromString("shadows.pcf_radius", "0");
    s->knobs().setFromString("shadows.enabled", "false");
    s->render({{"lbuffer"}});
    const FloatImage lit = s->readRaw("lbuffer");
    s->knobs().setFromString("shadows.enabled", "true");
    auto acne = [&](const char* constant, const char* slope) {
        s->knobs().setFromString("shadows.bias_constant", constant);
        s->knobs().setFromString("shadows.bias_slope", slope);
        s->render({{"lbuffer"}});
        const FloatImage L = s->readRaw("lbuffer");
        int dark = 0, n = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (lit.at(x, y, 0) <= 0.0f) continue;
                ++n;
                if (L.at(x, y, 0) < 0.97f * lit.at(x, y, 0)) ++dark;
            }
        return static_cast<double>(dark) / std::max(n, 1);
    };
    const double without = acne("0", "0");
    const double with = acne("1", "2.5");  // the defaults
    std::printf("shadow acne on an unoccluded plane: %.1f%% of pixels without bias, %.2f%% with\n", 100 * without, 100 * with);
    EXPECT_GT(without, 0.05);
    EXPECT_LT(with, 0.005);
}

INSTANTIATE_TEST_SUITE_P(Shadows, ShadowAcne,
                         ::testing::Values(glm::vec3(1.0f, -0.18f, 0.3f),  // about 80 degrees from the normal
                                           glm::vec3(0.0f, -1.0f, 0.0f)));

TEST(Shadows, ReusingOneMapGivesTheSameImageWithLessMemory) {
    auto s = test::makeSession(W, H);
    s->loadScene("street");
    s->knobs().setFromString("shadows.reuse_map", "true");
    s->render({{"lbuffer"}});
    const FloatImage reused = s->readRaw("lbuffer");
    const LightingPass& lighting = *s->pipeline().pass<LightingPass>();
    const ShadowPass& shadows = *s->pipeline().pass<ShadowPass>();
    const std::size_t inUseReused = shadows.bytesInUse(), keepingAll = shadows.bytesKeepingAll();
    s->knobs().setFromString("shadows.reuse_map", "false");
    s->render({{"lbuffer"}});
    const FloatImage kept = s->readRaw("lbuffer");
    EXPECT_EQ(test::maxAbsDifference(reused, kept, 3), 0.0);
    // The street's 9 shadowed lamps: one 1024^2 32-bit map in use instead of
    // one per light.
    const std::size_t map = 1024u * 1024u * 4u;
    const int shadowed = lighting.lastCounts().shadowed;
    EXPECT_EQ(shadowed, 9);
    EXPECT_EQ(inUseReused, map);
    EXPECT_EQ(keepingAll, map * static_cast<std::size_t>(shadowed));
    EXPECT_EQ(shadows.bytesInUse(), keepingAll);  // what keeping them all costs
    EXPECT_EQ(shadows.mapsRendered(), shadowed);
}

TEST(Bloom, AddsEnergyOnlyAroundPixelsAboveTheThreshold) {
    auto s = test::makeSession(W, H);
    Scene scene = test::planeScene(40.0f);
    scene.ambient = glm::vec3(0.1f);
    Material glow;
    glow.baseColor = glm::vec4(1.0f);
    glow.emissive = glm::vec3(200.0f, 150.0f, 80.0f);
    const int mat = scene.addMaterial(glow);
    Mesh bulb = shapes::box(glm::vec3(0.3f));
    bulb.material = mat;
    scene.instances.push_back({scene.addMesh(std::move(bulb)), glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 0.0f})});
    s->setScene(std::move(scene));
    s->knobs().setFromString("aa.method", "none");
    // The threshold is relative to the average luminance: without the black
    // background in the average, the floor stays below it and only the bulb blooms.
    s->knobs().setFromString("luminance.background", "exclude");
    for (const char* method : {"mip_sum", "dual_filter"}) {
        for (const char* composite : {"ldr_luminance_alpha", "hdr_add"}) {
            s->knobs().setFromString("bloom.method", method);
            s->knobs().setFromString("bloom.composite", composite);
            s->knobs().setFromString("bloom.levels", "2");
            s->knobs().setFromString("bloom.enabled", "false");
            s->render();
            const FloatImage off = s->readRaw("final");
            s->knobs().setFromString("bloom.enabled", "true");
            s->render();
            const FloatImage on = s->readRaw("final");
            const glm::ivec2 c = project(*s, {0.0f, 0.5f, 0.0f});
            double brightest = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x)
                    for (int ch = 0; ch < 3; ++ch) {
                        const double d = on.at(x, y, ch) - off.at(x, y, ch);
                        EXPECT_GE(d, -1.5 / 255.0) << method << " removed energy at " << x << "," << y;
                        const double dist = std::hypot(x - c.x, y - c.y);
                        // Two levels of half resolution: even the dual filter's 13-tap
                        // downsamples and tents reach under 40 pixels.
                        if (dist > 40) {
                            EXPECT_LE(std::fabs(d), 1.5 / 255.0) << method << " far from the light at " << x << "," << y;
                        }
                        if (dist < 12) brightest = std::max(brightest, d);
                    }
            EXPECT_GT(brightest, 0.05) << method << " " << composite;
        }
    }
    // Nothing above a threshold of 10^4 times the average: no bloom at all.
    s->knobs().setFromString("bloom.threshold", "10000");
    s->render({{"bloom.result"}});
    EXPECT_EQ(test::stats(s->readRaw("bloom.result"), 0).max, 0.0);
}

// The threshold pass averages each 2x2 block of the L-buffer before
// thresholding: a one-pixel highlight is neither dropped nor picked up by
// one block in four (which would flicker as the camera moves).
TEST(Bloom, BrightImageIsTheThresholded2x2MeanOfTheLBuffer) {
    auto s = test::makeSession(W, H);
    s->loadScene("street");
    s->knobs().setFromString("bloom.threshold", "1");
    s->render({{"bloom.bright", "lbuffer", "luminance.stats"}});
    const FloatImage L = s->readRaw("lbuffer");
    const FloatImage bright = s->readRaw("bloom.bright");
    const FloatImage stats = s->readRaw("luminance.stats");
    ASSERT_EQ(bright.width, W / 2);
    const double t = 1.0 * stats.at(0, 0, 0);
    int above = 0;
    double worst = 0.0;
    for (int y = 0; y < bright.height; ++y)
        for (int x = 0; x < bright.width; ++x) {
            glm::dvec3 c(0.0);
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i)
                    for (int ch = 0; ch < 3; ++ch) c[ch] += 0.25 * L.at(2 * x + i, 2 * y + j, ch);
            const double lum = reference::luminance(c.r, c.g, c.b);
            const glm::dvec3 want = lum > t ? c * ((lum - t) / lum) : glm::dvec3(0.0);
            above += lum > t;
            for (int ch = 0; ch < 3; ++ch) {
                const double err = std::fabs(bright.at(x, y, ch) - want[ch]) / std::max(1.0, std::fabs(want[ch]));
                worst = std::max(worst, err);
            }
        }
    EXPECT_GT(above, 5);  // the lamps
    EXPECT_LT(worst, 2e-3) << "half-float storage allows about 1e-3";
}

// An image so small that the half-size bright image has no coarser level
// still blooms (from the bright image itself), with both methods.
TEST(Bloom, ATinyImageStillBlooms) {
    for (const char* method : {"mip_sum", "dual_filter"}) {
        auto s = test::makeSession(3, 3);
        Scene scene = test::planeScene(40.0f);
        scene.materials[0].emissive = glm::vec3(50.0f);
        scene.camera.position = {0.0f, 5.0f, 0.01f};
        scene.camera.target = {0.0f, 0.0f, 0.0f};
        s->setScene(std::move(scene));
        s->knobs().setFromString("bloom.method", method);
        s->knobs().setFromString("bloom.threshold", "0");
        s->render({{"bloom.result"}});
        EXPECT_GT(test::stats(s->readRaw("bloom.result"), 0).min, 1.0) << method;
    }
}

// Before issue 10 this sky poisoned the bloom unless the guard was on; the sky
// pass now writes finite values (NaN 0, infinities 65504), so nothing
// non-finite reaches the bloom with the guard off or on.
TEST(NanGuard, NanAndInfinityInTheSkyNeverReachTheBloom) {
    auto s = test::makeSession(W, H);
    Scene scene = test::planeScene(20.0f);
    scene.sky.kind = Sky::Kind::Environment;
    scene.sky.equirect = FloatImage{64, 32, 3, std::vector<float>(64 * 32 * 3, 0.5f)};
    // A few NaN and infinite texels, as in OpenEXR's BrightRingsNanInf test image.
    for (int y = 0; y < 16; y += 3)
        for (int x = 0; x < 64; x += 5) {
            scene.sky.equirect.at(x, y, 1) = std::numeric_limits<float>::quiet_NaN();
            scene.sky.equirect.at((x + 2) % 64, y, 0) = std::numeric_limits<float>::infinity();
        }
    scene.camera.position = {0.0f, 2.0f, 8.0f};
    scene.camera.target = {0.0f, 2.5f, 0.0f};
    s->setScene(std::move(scene));
    s->knobs().setFromString("tonemap.nan_guard", "false");
    s->render({{"final", "bloom.result", "sky"}});
    EXPECT_EQ(test::stats(s->readRaw("sky"), 1).nonFinite, 0);
    EXPECT_EQ(test::stats(s->readRaw("bloom.result"), 1).nonFinite, 0);
    EXPECT_GT(test::stats(s->readRaw("bloom.result"), 0).max, 0.0);  // the bright sky still blooms
    s->knobs().setFromString("tonemap.nan_guard", "true");
    s->render({{"final", "bloom.result"}});
    EXPECT_EQ(test::stats(s->readRaw("bloom.result"), 1).nonFinite, 0);
    // The statistics skip non-finite pixels either way.
    EXPECT_GT(s->readRaw("luminance.stats").at(0, 0, 0), 0.0f);
}

TEST(Sky, FillsOnlyThePixelsWithoutGeometry) {
    auto s = test::makeSession(W, H);
    Scene scene = test::planeScene(10.0f);
    scene.background = glm::vec3(0.25f, 0.0f, 0.0f);
    scene.sky.kind = Sky::Kind::Procedural;
    scene.lights.push_back([] {
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
        return sun;
    }());
    s->setScene(std::move(scene));
    s->knobs().setFromString("skybox.mode", "color");
    const FrameReport colorReport = s->render({{"lbuffer", "gbuffer.depth"}});
    EXPECT_FALSE(colorReport.find("skybox")->ran);
    EXPECT_NE(colorReport.find("skybox")->reason.find("background colour"), std::string::npos);
    const FloatImage flat = s->readRaw("lbuffer");
    const FloatImage depth = s->readRaw("gbuffer.depth");
    s->knobs().setFromString("skybox.mode", "procedural");
    EXPECT_TRUE(s->render({{"lbuffer"}}).find("skybox")->ran);
    const FloatImage sky = s->readRaw("lbuffer");
    int background = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (!DepthConvention().isFar(depth.at(x, y, 0))) {
                for (int c = 0; c < 3; ++c) ASSERT_EQ(sky.at(x, y, c), flat.at(x, y, c)) << x << "," << y;
            } else {
                ++background;
                EXPECT_FLOAT_EQ(flat.at(x, y, 0), 0.25f);
                EXPECT_GT(sky.at(x, y, 2), sky.at(x, y, 0) * 0.5f);  // a blue-ish sky, not the red background
            }
        }
    EXPECT_GT(background, W * H / 10);
    s->knobs().setFromString("skybox.mode", "environment");
    EXPECT_NE(s->render().find("skybox")->reason.find("no environment map"), std::string::npos);
}

TEST(DepthOfField, SharpInFocusAndBlurredAwayFromIt) {
    auto s = test::makeSession(W, H);
    s->loadScene("spheres");
    s->knobs().setFromString("aa.method", "none");
    s->knobs().setFromString("dof.enabled", "true");
    s->knobs().setFromString("dof.focus_distance", "10");
    s->knobs().setFromString("dof.focus_range", "1000");
    s->render({{"final", "tonemap.result"}});
    EXPECT_EQ(test::maxAbsDifference(s->readRaw("dof.result"), s->readRaw("tonemap.result"), 3), 0.0);
    s->knobs().setFromString("dof.focus_distance", "1");
    s->knobs().setFromString("dof.focus_range", "0.5");
    s->render({{"final", "tonemap.result", "dof.coc"}});
    const FloatImage sharp = s->readRaw("tonemap.result"), blurred = s->readRaw("dof.result");
    auto detail = [](const FloatImage& img) {
        double sum = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 1; x < W; ++x) sum += std::fabs(img.at(x, y, 1) - img.at(x - 1, y, 1));
        return sum;
    };
    EXPECT_LT(detail(blurred), detail(sharp) * 0.7);
    EXPECT_GT(test::stats(s->readRaw("dof.coc"), 0).max, 3.0);  // everything is behind the focus
}

TEST(Fxaa, ChangesOnlyPixelsOnEdges) {
    auto s = test::makeSession(W, H);
    s->loadScene("spheres");
    s->render({{"final", "tonemap.result"}});
    const FloatImage in = s->readRaw("tonemap.result"), out = s->readRaw("final");
    int changed = 0;
    for (int y = 1; y < H - 1; ++y)
        for (int x = 1; x < W - 1; ++x) {
            if (std::fabs(in.at(x, y, 1) - out.at(x, y, 1)) < 1e-6f) continue;
            ++changed;
            double lo = 1, hi = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const double l = 0.299 * in.at(x + dx, y + dy, 0) + 0.587 * in.at(x + dx, y + dy, 1) + 0.114 * in.at(x + dx, y + dy, 2);
                    lo = std::min(lo, l);
                    hi = std::max(hi, l);
                }
            EXPECT_GT(hi - lo, 0.0312 - 1e-3) << "FXAA changed a flat pixel at " << x << "," << y;
        }
    EXPECT_GT(changed, 50);
    EXPECT_LT(changed, W * H / 3);
}

// FXAA against the answer it approximates: the same frame rendered at 4x4
// the size and box-filtered down. On the pixels along edges it must come
// closer to that than the aliased image does, at every quality.
TEST(Fxaa, MovesEdgePixelsTowardsASupersampledReference) {
    auto frame = [](int w, int h, const char* fxaa, const char* quality) {
        auto s = test::makeSession(w, h);
        s->loadScene("spheres");
        for (const char* k : {"ao.enabled=false", "bloom.enabled=false", "tonemap.operator=clamp", "tonemap.exposure=-1"})
            s->knobs().applyAssignment(k);
        s->knobs().setFromString("aa.method", fxaa);
        s->knobs().setFromString("fxaa.quality", quality);
        s->render();
        return s->readRaw("final");
    };
    const FloatImage big = frame(4 * W, 4 * H, "none", "medium");
    FloatImage ref{W, H, 3, std::vector<float>(W * H * 3, 0.0f)};
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                float sum = 0.0f;
                for (int j = 0; j < 4; ++j)
                    for (int i = 0; i < 4; ++i) sum += big.at(4 * x + i, 4 * y + j, ch);
                ref.at(x, y, ch) = sum / 16.0f;
            }
    const FloatImage aliased = frame(W, H, "none", "medium");
    // Edge pixels: where the aliased image is far from the reference.
    auto error = [&](const FloatImage& img) {
        double e = 0.0;
        int n = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (std::fabs(aliased.at(x, y, 1) - ref.at(x, y, 1)) < 0.1f) continue;
                ++n;
                for (int ch = 0; ch < 3; ++ch) e += std::fabs(img.at(x, y, ch) - ref.at(x, y, ch));
            }
        return std::make_pair(e / std::max(n, 1), n);
    };
    const auto [aliasedError, edges] = error(aliased);
    ASSERT_GT(edges, 30);
    for (const char* q : {"low", "medium", "high"}) {
        const double e = error(frame(W, H, "fxaa", q)).first;
        std::printf("FXAA %s: mean error on %d edge pixels %.4f (aliased %.4f)\n", q, edges, e, aliasedError);
        EXPECT_LT(e, 0.8 * aliasedError) << q;
    }
}

TEST(Effects, SwitchingAnEffectOffRemovesItsPass) {
    auto s = test::makeSession(96, 54);
    s->loadScene("default");
    const auto all = ran(s->render());
    for (const char* p : {"geometry", "ao", "ao_filter", "skybox", "lighting", "luminance", "bloom", "tonemap", "fxaa"})
        EXPECT_TRUE(has(all, p)) << p;
    EXPECT_FALSE(has(all, "dof"));
    struct Toggle {
        const char* knob;
        const char* value;
        std::vector<const char*> gone;
    };
    for (const Toggle& t : {Toggle{"ao.enabled", "false", {"ao", "ao_filter"}}, Toggle{"bloom.enabled", "false", {"bloom"}},
                            Toggle{"aa.method", "none", {"fxaa"}}, Toggle{"skybox.mode", "color", {"skybox"}}}) {
        KnobRegistry saved = s->knobs();
        s->knobs().setFromString(t.knob, t.value);
        const FrameReport r = s->render();
        for (const char* p : t.gone) {
            EXPECT_FALSE(r.find(p)->ran) << t.knob;
            EXPECT_FALSE(r.find(p)->reason.empty()) << t.knob;
        }
        s->knobs() = saved;
    }
    s->knobs().setFromString("dof.enabled", "true");
    EXPECT_TRUE(has(ran(s->render()), "dof"));
    EXPECT_EQ(s->pipeline().resolveFinal(), "fxaa.result");
    s->knobs().setFromString("aa.method", "none");
    EXPECT_EQ(s->pipeline().resolveFinal(), "dof.result");
    // Shadows are part of lighting: switched off, no map is rendered and no time is spent on them.
    s->knobs().setFromString("shadows.enabled", "false");
    s->render();
    EXPECT_EQ(s->pipeline().pass<LightingPass>()->lastCounts().shadowed, 0);
    EXPECT_EQ(s->render().find("lighting")->stats.find("shadow maps"), std::string::npos);
}
