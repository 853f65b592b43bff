// Spot lights with KHR_lights_punctual's cone (issue 25; case
// gltf_spot_inner_outer_cone.gltf): full intensity inside the inner cone,
// the square of a linear ramp in cos(theta) between the cones, 0 at the outer
// cone with no rim; the seeds' cutoff and exponent stay for the others. Every
// lighting strategy, the shadowed path and the CPU reference agree on both.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "renderer/reference/ShadingReference.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/GltfBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;
using nlohmann::json;

namespace {

constexpr double kInner = 0.2, kOuter = 0.6;

// The extension's falloff at angle theta (KHR_lights_punctual, "Inner and
// Outer Cone Angles"), written out here rather than taken from the renderer.
double extensionFalloff(double theta) {
    const double t = std::clamp((std::cos(theta) - std::cos(kOuter)) / (std::cos(kInner) - std::cos(kOuter)), 0.0, 1.0);
    return t * t;
}

// The case's file (with a matte material): a 16 x 16 floor at y = 0, a spot of intensity 30 at
// (0, 3, 0) pointing down (inner 0.2, outer 0.6 rad), the camera 9 above it
// looking down (yfov 0.9).
json spotCaseGltf() {
    test::GltfBuilder b;
    const int pos = b.vec3({-8, 0, -8, 8, 0, -8, 8, 0, 8, -8, 0, 8});
    const int nrm = b.vec3({0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0});
    const int idx = b.indices({0, 2, 1, 0, 3, 2});
    json j = b.finish({{"POSITION", pos}, {"NORMAL", nrm}}, idx);
    const json down = {-0.70710678, 0, 0, 0.70710678};
    // A matte floor (no specular lobe), so the light's falloff, distance and
    // incidence are all that vary; the case's file has the default material.
    j["materials"] = json::array({{{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 1}}},
                                   {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0}}}}}}});
    j["meshes"][0]["primitives"][0]["material"] = 0;
    j["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_specular"};
    j["extensions"]["KHR_lights_punctual"]["lights"] = json::array(
        {{{"type", "spot"}, {"intensity", 30}, {"color", {1, 1, 1}},
          {"spot", {{"innerConeAngle", kInner}, {"outerConeAngle", kOuter}}}}});
    j["nodes"].push_back({{"translation", {0, 3, 0}}, {"rotation", down}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    j["nodes"].push_back({{"translation", {0, 9, 0}}, {"rotation", down}, {"camera", 0}});
    j["scenes"][0]["nodes"] = {0, 1, 2};
    j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}, {"zfar", 50}}}}});
    return j;
}

// The strategies that shade bounded lights.
const char* const kStrategies[] = {"stencil_volumes", "volumes", "fullscreen", "tiled", "clustered", "forward",
                                   "forward_multipass"};

// |a - b| relative to the larger value plus `floor`, worst over RGB.
double worstRelative(const FloatImage& a, const FloatImage& b, double floor) {
    double worst = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double va = a.at(x, y, c), vb = b.at(x, y, c);
                worst = std::max(worst, std::fabs(va - vb) / (std::max(std::fabs(va), std::fabs(vb)) + floor));
            }
    return worst;
}

}  // namespace

// The case's measurement: along the row through the light's axis, each
// pixel's L-buffer value less the ambient light's, relative to the pixel
// nearest the axis. At angle
// theta from the axis the floor at distance 3 / cos(theta) receives
// falloff(theta) cos^3(theta) of the centre (1/d^2 and the incidence): 0.955
// at 0.175 rad (inside the inner cone only distance and incidence count), 0.005
// at 0.575, 0 from 0.6 on. Before, the loader fitted an exponent: 0.841 at
// 0.175, 0.149 at 0.575 and a hard rim at 0.6.
TEST(SpotCone, GltfSpotFollowsTheExtensionsFalloff) {
    constexpr int S = 320;
    auto s = test::makeSession(S, S);
    s->loadScene(test::writeJson("spot_cone.gltf", spotCaseGltf()).string());
    ASSERT_EQ(s->scene().lights.size(), 1u);
    EXPECT_EQ(s->scene().lights[0].falloff, SpotFalloff::InnerOuterCone);
    s->knobs().setFromString("ao.enabled", "false");
    s->render({{"lbuffer", "gbuffer.view_position"}});
    const FloatImage L = s->readRaw("lbuffer"), P = s->readRaw("gbuffer.view_position");
    // The light in view space: 6 in front of the camera, pointing away from it.
    const glm::dvec3 light(0.0, 0.0, -6.0);
    const int y = S / 2;
    auto angle = [&](int x) {
        const glm::dvec3 p(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2));
        return std::acos(std::clamp(-(p - light).z / glm::length(p - light), -1.0, 1.0));
    };
    int centre = 0;
    for (int x = 0; x < S; ++x)
        if (angle(x) < angle(centre)) centre = x;
    // The scene's ambient light, the same over the whole floor: the value
    // at the row's end, far outside the cone.
    ASSERT_GT(angle(S - 1), kOuter + 0.2);
    const double ambient = L.at(S - 1, y, 0);
    auto spot = [&](int x) { return L.at(x, y, 0) - ambient; };
    const double c0 = spot(centre), cos0 = std::cos(angle(centre));
    ASSERT_GT(c0, 0.0);
    double worst = 0.0, at175 = -1, at575 = -1, best175 = 1, best575 = 1, rim = 0.0;
    int lit = 0, dark = 0;
    for (int x = centre; x < S; ++x) {
        const double theta = angle(x), got = spot(x) / c0;
        const double expected = extensionFalloff(theta) * std::pow(std::cos(theta) / cos0, 3.0);
        worst = std::max(worst, std::fabs(got - expected));
        if (std::fabs(theta - 0.175) < best175) best175 = std::fabs(theta - 0.175), at175 = got;
        if (std::fabs(theta - 0.575) < best575) best575 = std::fabs(theta - 0.575), at575 = got;
        if (theta > 0.59 && theta < kOuter) rim = std::max(rim, got);
        if (theta >= kOuter) dark += std::fabs(got) < 1e-5 ? 1 : 0;
        if (theta < kOuter) ++lit;
        if (x > centre) {
            EXPECT_LE(got, spot(x - 1) / c0 + 1e-6) << "not falling off at x = " << x;
        }
    }
    std::printf("relative to the centre: %.4f at 0.175 rad, %.4f at 0.575 rad, at most %.5f over 0.59-0.6 rad; "
                "worst deviation from the extension %.4f over %d lit pixels\n",
                at175, at575, rim, worst, lit);
    ASSERT_GT(lit, 60);
    EXPECT_NEAR(at175, 0.955, 0.01);
    EXPECT_NEAR(at575, 0.005, 0.0035);
    EXPECT_LT(rim, 0.002);  // no rim at the outer cone
    EXPECT_GT(dark, 20);
    EXPECT_LT(worst, 2e-3);
}

// Both falloff models, one spot of each (the cone one also with a shadow map
// on an open floor, which must change nothing), against the CPU double-
// precision reference in every strategy, and every strategy against the
// full-screen one.
TEST(SpotCone, EveryStrategyAndTheCpuReferenceAgreeForBothFalloffs) {
    constexpr int W = 160, H = 90;
    auto s = test::makeSession(W, H);
    Scene scene = test::planeScene(40.0f);
    Light& seed = test::addSpotLight(scene, {-2.5f, 3.0f, 0.0f}, {0.2f, -1.0f, 0.1f}, 35.0f, 6.0f, glm::vec3(6.0f),
                                     {1.0f, 0.1f, 0.2f});
    (void)seed;
    Light& cone = test::addSpotLight(scene, {2.0f, 3.5f, 0.5f}, {-0.1f, -1.0f, -0.2f}, 40.0f, 0.0f, glm::vec3(8.0f),
                                     {1.0f, 0.1f, 0.2f});
    cone.falloff = SpotFalloff::InnerOuterCone;
    cone.innerConeDegrees = 15.0f;
    const std::vector<Light> lights = scene.lights;
    s->setScene(std::move(scene));
    s->knobs().setFromString("ao.enabled", "false");
    const double threshold = s->knobs().value(*s->knobs().find("lighting.threshold"));
    FloatImage brute;
    for (const char* strategy : kStrategies) {
        s->knobs().setFromString("lighting.strategy", strategy);
        s->render({{"lbuffer", "gbuffer.view_position", "gbuffer.view_normal"}});
        const FloatImage L = s->readRaw("lbuffer");
        const test::GBufferImages g = test::readGBuffer(*s);
        const glm::dmat4 view = s->pipeline().lastCamera().worldToView();
        double worst = 0.0;
        int checked = 0, inRamp = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (!g.surface(x, y)) continue;
                const glm::dvec3 expected = test::referenceRadiance(lights, view, g.at(x, y), threshold);
                worst = std::max(worst, std::fabs(L.at(x, y, 0) - expected.x) / (std::fabs(expected.x) + 0.01));
                ++checked;
                // Pixels between the cone light's inner and outer cone.
                const glm::dvec3 p = glm::dvec3(glm::inverse(view) * glm::dvec4(g.at(x, y).position, 1.0));
                const double cosTheta = glm::dot(glm::normalize(p - glm::dvec3(lights[1].position)),
                                                 glm::normalize(glm::dvec3(lights[1].direction)));
                if (cosTheta < std::cos(glm::radians(15.0)) && cosTheta > std::cos(glm::radians(40.0))) ++inRamp;
            }
        std::printf("%s: worst relative error against the CPU reference %.3g over %d pixels (%d in the cone's ramp)\n",
                    strategy, worst, checked, inRamp);
        EXPECT_GT(inRamp, 300) << strategy;
        EXPECT_LT(worst, 1e-2) << strategy;
        if (std::string(strategy) == "fullscreen") brute = L;
    }
    for (const char* strategy : kStrategies) {
        s->knobs().setFromString("lighting.strategy", strategy);
        s->render({{"lbuffer"}});
        EXPECT_LT(worstRelative(s->readRaw("lbuffer"), brute, 1e-3), 5e-3) << strategy;
    }
    // The cone light with a shadow map on an open floor: the same image.
    s->mutableScene().lights[1].castShadows = true;
    for (const char* strategy : {"stencil_volumes", "tiled", "forward"}) {
        s->knobs().setFromString("lighting.strategy", strategy);
        s->render({{"lbuffer"}});
        EXPECT_LT(worstRelative(s->readRaw("lbuffer"), brute, 1e-3), 1e-2) << strategy << " with a shadow map";
    }
}

// The CPU reference's spot factor for both models.
TEST(SpotCone, ReferenceSpotFactor) {
    Light l;
    l.type = LightType::Spot;
    l.cutoffDegrees = static_cast<float>(glm::degrees(kOuter));
    l.exponent = 4.0f;
    EXPECT_NEAR(reference::spotFactor(l, std::cos(0.3)), std::pow(std::cos(0.3), 4.0), 1e-12);
    EXPECT_EQ(reference::spotFactor(l, std::cos(0.61)), 0.0);
    l.falloff = SpotFalloff::InnerOuterCone;
    l.innerConeDegrees = static_cast<float>(glm::degrees(kInner));
    EXPECT_NEAR(reference::spotFactor(l, std::cos(0.1)), 1.0, 1e-12);
    EXPECT_NEAR(reference::spotFactor(l, std::cos(0.575)), extensionFalloff(0.575), 1e-6);
    EXPECT_NEAR(reference::spotFactor(l, std::cos(0.575)), 0.00797, 1e-4);
    EXPECT_EQ(reference::spotFactor(l, std::cos(0.61)), 0.0);
}
