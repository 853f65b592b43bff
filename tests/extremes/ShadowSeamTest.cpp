// Point-light shadow maps at face seams and with wide PCF (issue 10, case
// point_shadow_cube_seams.json re-created small): every floor pixel that no
// blocker hides equals the shadows-off render within 1%, for pcf_radius 0..3,
// cube and dual-paraboloid maps and a spot wider than 60 degrees; the box's
// own shadow is still there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/scene/SceneJsonLoader.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

const char* kSeamScene = R"({
  "camera": { "pos": [0, 9, 9], "look-at": [0, 0, 0], "up": [0, 1, 0], "fov": 55, "near": 0.1, "far": 60 },
  "ambient": [0, 0, 0],
  "sky": { "type": "color" },
  "lights": [ LIGHT ],
  "objects": [
    { "shape": "plane", "size": [30, 0, 30], "material": { "diffuse": [0.8, 0.8, 0.8], "specular": [0, 0, 0] } },
    { "shape": "box", "size": [1, 1, 1], "pos": [1.5, 2, 0], "material": { "diffuse": [0.8, 0.3, 0.3], "specular": [0, 0, 0] } }
  ]
})";

const char* kPointLight =
    R"({ "name": "bulb", "type": "point", "pos": [0, 4, 0], "shadow": true, "intensity": [3, 3, 3], "attenuation": { "constant": 1, "linear": 0, "quadratic": 0.02 } })";
const char* kWideSpot =
    R"({ "name": "wide", "pos": [0, 4, 0], "direction": [0, -1, 0], "cutoff": 80, "exponent": 0, "shadow": true, "intensity": [3, 3, 3], "attenuation": { "constant": 1, "linear": 0, "quadratic": 0.02 } })";

Scene seamScene(const char* light) {
    std::string text = kSeamScene;
    text.replace(text.find("LIGHT"), 5, light);
    return parseSceneJson(text, "point_shadow_cube_seams.json");
}

// Whether the segment from p to the light passes within `margin` of the box
// (the blocker at (1.5, 2, 0), unit size): its shadow and penumbra.
bool nearBlockerShadow(const glm::vec3& p, const glm::vec3& light, float margin) {
    const glm::vec3 lo = glm::vec3(1.0f, 1.5f, -0.5f) - margin, hi = glm::vec3(2.0f, 2.5f, 0.5f) + margin;
    const glm::vec3 d = light - p;
    float t0 = 0.0f, t1 = 1.0f;
    for (int a = 0; a < 3; ++a) {
        if (std::fabs(d[a]) < 1e-9f) {
            if (p[a] < lo[a] || p[a] > hi[a]) return false;
            continue;
        }
        float ta = (lo[a] - p[a]) / d[a], tb = (hi[a] - p[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

struct SeamResult {
    double worstOpenFloor = 0.0;  // largest |shadowed / unshadowed - 1| on open floor
    int openFloor = 0, blocked = 0;  // pixels counted; pixels darker than half in the box's shadow
};

SeamResult compareWithShadowsOff(const char* light, const char* method, int pcf) {
    const int W = 192, H = 108;
    auto session = test::makeSession(W, H);
    session->setScene(seamScene(light));
    session->knobs().setFromString("shadows.point_method", method);
    session->knobs().setFromString("shadows.map_size", "256");
    session->knobs().setFromString("shadows.pcf_radius", std::to_string(pcf));
    session->knobs().setFromString("ao.enabled", "false");
    session->render({{"lbuffer", "gbuffer.view_position"}});
    const FloatImage shadowed = session->readRaw("lbuffer");
    const FloatImage position = session->readRaw("gbuffer.view_position");
    const glm::mat4 inverseView(glm::inverse(session->pipeline().lastCamera().worldToView()));
    session->knobs().setFromString("shadows.enabled", "false");
    session->render({{"lbuffer"}});
    const FloatImage open = session->readRaw("lbuffer");
    SeamResult r;
    const glm::vec3 lightPos(0.0f, 4.0f, 0.0f);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (position.at(x, y, 3) == 0.0f) continue;
            const glm::vec3 world(inverseView * glm::vec4(position.at(x, y, 0), position.at(x, y, 1), position.at(x, y, 2), 1.0f));
            if (std::fabs(world.y) > 1e-3f) continue;  // the floor only
            const double base = open.at(x, y, 0);
            if (base < 1e-3) continue;
            const double ratio = shadowed.at(x, y, 0) / base;
            if (nearBlockerShadow(world, lightPos, 0.0f) && ratio < 0.5) ++r.blocked;
            // Leave out the shadow and its PCF penumbra: every floor point
            // the lookup's taps reach (shaders/common/shadow.glsl: a grid in
            // the receiver's plane, 2 texel angles apart at the light's
            // distance over the incidence cosine), one tap of slack.
            const float len = glm::length(world - lightPos);
            const float step = 2.0f / 256.0f * len / std::max(4.0f / len, 0.25f);
            bool penumbra = false;
            for (int j = -pcf - 1; j <= pcf + 1 && !penumbra; ++j)
                for (int i = -pcf - 1; i <= pcf + 1 && !penumbra; ++i)
                    penumbra = nearBlockerShadow(world + glm::vec3(i * step, 0.0f, j * step), lightPos, 0.05f);
            if (penumbra) continue;
            ++r.openFloor;
            r.worstOpenFloor = std::max(r.worstOpenFloor, std::fabs(ratio - 1.0));
        }
    return r;
}

}  // namespace

class PointShadowSeams : public ::testing::TestWithParam<std::tuple<const char*, int>> {};

TEST_P(PointShadowSeams, OpenFloorEqualsShadowsOffWithinOnePercent) {
    const auto [method, pcf] = GetParam();
    const SeamResult r = compareWithShadowsOff(kPointLight, method, pcf);
    std::printf("%s pcf %d: open floor %d px, worst |ratio - 1| %.4f, %d px in the box's shadow\n", method, pcf,
                r.openFloor, r.worstOpenFloor, r.blocked);
    EXPECT_GT(r.openFloor, 192 * 108 / 3);
    EXPECT_LT(r.worstOpenFloor, 0.01);
    EXPECT_GT(r.blocked, 20);  // the blocker still casts its shadow
}

INSTANTIATE_TEST_SUITE_P(PcfRadius, PointShadowSeams,
                         ::testing::Combine(::testing::Values("cube", "dual_paraboloid"), ::testing::Values(0, 1, 2, 3)),
                         [](const auto& p) {
                             return std::string(std::get<0>(p.param)) + "_pcf" + std::to_string(std::get<1>(p.param));
                         });

TEST(PointShadowSeams, SpotWiderThanSixtyDegreesUsesTheCubeWithoutSeams) {
    for (int pcf : {0, 3}) {
        const SeamResult r = compareWithShadowsOff(kWideSpot, "cube", pcf);
        std::printf("wide spot pcf %d: open floor %d px, worst |ratio - 1| %.4f, %d px in the box's shadow\n", pcf,
                    r.openFloor, r.worstOpenFloor, r.blocked);
        EXPECT_GT(r.openFloor, 1000);
        EXPECT_LT(r.worstOpenFloor, 0.01);
        EXPECT_GT(r.blocked, 20);
    }
}
