// Every ambient-occlusion method registered for ao.method (issue 22), looped
// over the registry so a method added later is tested without a line here:
// AO = 1 on an open plane, and near the ray-traced AO of renderer/reference
// (cosine-weighted rays, the same radius) in a right-angle crease and under a
// raised box. The tolerances are per method, measured on llvmpipe at
// 160x90 and stated below with the values they guard.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <algorithm>
#include <map>

#include "renderer/passes/AoPass.h"
#include "renderer/reference/ReferenceModel.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

constexpr int W = 160, H = 90;

// The tolerance on the mean |AO - ray-traced AO| over a region, per method;
// a method missing here gets kDefaultTolerance.
struct Tolerance {
    double crease;  // the floor along the wall's foot
    double box;     // the floor under the raised box
};
const std::map<std::string, Tolerance> kTolerance = {
    // SSAO's kernel in the ball, falloff and half-size buffer: measured 0.153
    // in the crease and 0.415 under the box (0.74 against 0.33: the box's
    // underside is not in the depth buffer, and its definition is not the
    // cosine-weighted visibility; docs/ao.md).
    {"ssao", {0.20, 0.45}},
    // GTAO at its defaults (3 slices x 3 steps, full size): measured 0.055 and
    // 0.074 (0.067 with gtao.thin_occluders=0: a few slices take a box edge
    // for a thin occluder; docs/ao.md, "Thin occluders").
    {"gtao", {0.08, 0.09}},
    // With its own 5x5 edge-aware denoise instead of the shared blur: measured 0.043 and 0.060.
    {"gtao gtao.denoise=edge_aware", {0.08, 0.09}},
    // AOV at full size (radius 1, falloff 1): measured 0.026 and 0.008 (the
    // box's underside is a plane facing the floor, AOV's exact case; docs/aov.md).
    {"aov", {0.04, 0.03}},
};
constexpr Tolerance kDefaultTolerance{0.25, 0.25};

std::vector<std::string> methodNames() {
    auto s = test::makeSession(8, 8);
    std::vector<std::string> names;
    for (const auto& m : s->pipeline().pass<AoPass>()->methods()) names.emplace_back(m->name());
    return names;
}

// Every registered method at its defaults, and GTAO with its own denoise
// too. A variant is "method" or "method knob=value".
std::vector<std::string> variants() {
    std::vector<std::string> v = methodNames();
    if (std::find(v.begin(), v.end(), "gtao") != v.end()) v.push_back("gtao gtao.denoise=edge_aware");
    return v;
}

// The variant at full resolution, so ao.raw and the reference share pixels.
void choose(RenderSession& s, const std::string& variant) {
    const std::string method = variant.substr(0, variant.find(' '));
    s.knobs().setFromString("ao.method", method);
    const std::string resolution = method + ".resolution";
    if (s.knobs().find(resolution)) s.knobs().setFromString(resolution, "full");
    if (variant.find(' ') != std::string::npos) s.knobs().applyAssignment(variant.substr(variant.find(' ') + 1));
}

Scene withAmbient(Scene s) {
    s.ambient = glm::vec3(0.2f);
    return s;
}

// The floor with a wall along x = 0 (a right-angle crease at its foot) and
// a 2 x 0.5 x 2 box whose underside is 0.3 above the floor at x = 4, z = 0.
Scene creaseAndBox() {
    Scene scene = withAmbient(test::planeScene(40.0f));
    Mesh wall = shapes::box({0.4f, 4.0f, 20.0f});
    wall.material = 0;
    scene.instances.push_back({scene.addMesh(std::move(wall)), glm::translate(glm::mat4(1.0f), {-0.2f, 2.0f, 0.0f})});
    Mesh box = shapes::box({2.0f, 0.5f, 2.0f});
    box.material = 0;
    scene.instances.push_back({scene.addMesh(std::move(box)), glm::translate(glm::mat4(1.0f), {4.0f, 0.55f, 0.0f})});
    scene.camera.position = {6.0f, 3.0f, 7.0f};
    scene.camera.target = {1.5f, 0.0f, 0.0f};
    return scene;
}

struct Regions {
    double gpuCrease = 0, refCrease = 0, errCrease = 0;
    double gpuBox = 0, refBox = 0, errBox = 0;
    double gpuOpen = 0;
    int nCrease = 0, nBox = 0, nOpen = 0;
};

}  // namespace

TEST(AoMethods, TheRegistryHoldsSsaoAndGtao) {
    const std::vector<std::string> names = methodNames();
    ASSERT_GE(names.size(), 2u);
    EXPECT_EQ(names[0], "ssao");  // the default
    EXPECT_NE(std::find(names.begin(), names.end(), "gtao"), names.end());
}

TEST(AoMethods, AnOpenPlaneIsNotOccluded) {
    for (const std::string& method : variants()) {
        auto s = test::makeSession(W, H);
        s->setScene(withAmbient(test::planeScene(200.0f)));
        choose(*s, method);
        s->render({{"ao.raw", "ao.filtered"}});
        const auto raw = test::stats(s->readRaw("ao.raw"), 0);
        const auto filtered = test::stats(s->readRaw("ao.filtered"), 0);
        std::printf("%s open plane: ao.raw mean %.4f (min %.4f, max %.4f), ao.filtered mean %.4f (min %.4f)\n",
                    method.c_str(), raw.mean, raw.min, raw.max, filtered.mean, filtered.min);
        // ao.raw: 1 on average within 0.015 (GTAO's single pixels are not 1:
        // a slice's estimate is exact only on average over its directions).
        EXPECT_NEAR(raw.mean, 1.0, 0.015) << method;
        // ao.filtered, what the lighting uses: mean within 0.005 of 1, no pixel below 0.95.
        EXPECT_GT(filtered.mean, 0.995) << method;
        EXPECT_GT(filtered.min, 0.95) << method;
    }
}

TEST(AoMethods, ACreaseAndTheFloorUnderABoxApproachTheRayTracedAo) {
    const Scene scene = creaseAndBox();
    auto probe = test::makeSession(W, H);
    probe->setScene(Scene(scene));
    // The ray-traced AO once: every method's radius is 1 world unit here (the
    // scene's unit is 1), so one reference serves them all.
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(probe->knobs(), probe->scene());
    model.aoRays = 256;
    model.bakedOcclusion = false;
    ASSERT_TRUE(model.rayTracedAo);
    ASSERT_NEAR(model.aoRadius, 1.0, 1e-9);
    reference::ReferenceRequest request;
    request.camera = probe->camera();
    request.width = W;
    request.height = H;
    const reference::ReferenceImages ref = reference::renderReference(probe->scene(), model, request);

    probe->render({{"gbuffer.view_position"}});
    const FloatImage P = probe->readRaw("gbuffer.view_position");
    const glm::mat4 inverseView = glm::inverse(probe->camera().view());
    for (const std::string& method : variants()) {
        auto s = test::makeSession(W, H);
        s->setScene(Scene(scene));
        choose(*s, method);
        s->render({{"ao.filtered"}});
        const FloatImage ao = s->readRaw("ao.filtered");
        Regions r;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (P.at(x, y, 3) == 0.0f) continue;
                const glm::vec3 w(inverseView * glm::vec4(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2), 1.0f));
                if (w.y > 0.02f || std::abs(w.z) > 5.0f) continue;  // floor pixels only
                const double g = ao.at(x, y, 0), a = ref.ao.pixels[static_cast<size_t>(y) * W + x];
                if (w.x > 0.05f && w.x < 0.6f) {
                    r.gpuCrease += g, r.refCrease += a, r.errCrease += std::abs(g - a), ++r.nCrease;
                } else if (w.x > 3.2f && w.x < 4.8f && std::abs(w.z) < 0.8f) {
                    r.gpuBox += g, r.refBox += a, r.errBox += std::abs(g - a), ++r.nBox;
                } else if (w.x > 1.6f && w.x < 2.4f && std::abs(w.z) > 2.5f) {
                    r.gpuOpen += g, ++r.nOpen;
                }
            }
        ASSERT_GT(r.nCrease, 20) << method;
        ASSERT_GT(r.nBox, 20) << method;
        ASSERT_GT(r.nOpen, 20) << method;
        const auto it = kTolerance.find(method);
        const Tolerance tol = it == kTolerance.end() ? kDefaultTolerance : it->second;
        std::printf("%s: crease AO %.3f (ray-traced %.3f, mean |error| %.3f, %d px); under the box %.3f (ray-traced "
                    "%.3f, mean |error| %.3f, %d px); open floor %.3f\n",
                    method.c_str(), r.gpuCrease / r.nCrease, r.refCrease / r.nCrease, r.errCrease / r.nCrease, r.nCrease,
                    r.gpuBox / r.nBox, r.refBox / r.nBox, r.errBox / r.nBox, r.nBox, r.gpuOpen / r.nOpen);
        EXPECT_LT(r.errCrease / r.nCrease, tol.crease) << method;
        EXPECT_LT(r.errBox / r.nBox, tol.box) << method;
        // Occluded where the truth is: both regions darker than the open floor.
        EXPECT_LT(r.gpuCrease / r.nCrease, r.gpuOpen / r.nOpen - 0.05) << method;
        EXPECT_LT(r.gpuBox / r.nBox, r.gpuOpen / r.nOpen - 0.05) << method;
        EXPECT_GT(r.gpuOpen / r.nOpen, 0.97) << method;
    }
}

// tests/data/ao/thin_pole_before_wall.json (a user's case): a pole 0.06 wide
// 0.3 in front of a wall, at 240x180 as reported. The horizon takes the pole
// as infinitely thick and, before gtao.thin_occluders, shaded the wall beside
// it as a wall would: 0.802 against the ray-traced 0.929 within 6 px of the
// pole (0.799 against 0.913 in the report's region). At the defaults the
// region's mean is within 0.03 of the rays' (measured 0.913 against 0.929;
// scripts/gtao_thin_occluder_sweep.py, docs/ao.md); the compensation off,
// the old error is back (above 0.1), so the region does see the pole.
TEST(AoMethods, GtaoBesideAThinPoleStaysNearTheRayTracedAo) {
    constexpr int PW = 240, PH = 180;
    auto s = test::makeSession(PW, PH);
    s->loadScene(std::string(DW_TEST_AO_DIR) + "/thin_pole_before_wall.json");
    ASSERT_EQ(s->knobs().format(*s->knobs().find("ao.method")), "gtao");  // the scene's setting
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(s->knobs(), s->scene());
    model.aoRays = 64;
    model.bakedOcclusion = false;
    ASSERT_NEAR(model.aoRadius, 1.0, 1e-9);
    reference::ReferenceRequest request;
    request.camera = s->camera();
    request.width = PW;
    request.height = PH;
    const reference::ReferenceImages ref = reference::renderReference(s->scene(), model, request);
    s->render({{"gbuffer.view_position"}});
    const FloatImage P = s->readRaw("gbuffer.view_position");
    const glm::mat4 inverseView = glm::inverse(s->camera().view());
    // The wall (world z = 0) within 6 px, in the same row, of the pole (z > 0.1).
    auto worldZ = [&](int x, int y) {
        if (P.at(x, y, 3) == 0.0f) return -1e9f;
        return (inverseView * glm::vec4(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2), 1.0f)).z;
    };
    std::vector<std::pair<int, int>> region;
    for (int y = 0; y < PH; ++y)
        for (int x = 0; x < PW; ++x) {
            if (std::abs(worldZ(x, y)) > 0.05f) continue;
            for (int dx = -6; dx <= 6; ++dx)
                if (x + dx >= 0 && x + dx < PW && worldZ(x + dx, y) > 0.1f) {
                    region.emplace_back(x, y);
                    break;
                }
        }
    ASSERT_GT(region.size(), 500u);
    const int thin = *s->knobs().find("gtao.thin_occluders");
    auto meanAo = [&](bool compensated) {
        if (compensated) s->knobs().reset(thin);  // the default
        else s->knobs().setFromString("gtao.thin_occluders", "0");
        s->render({{"ao.filtered"}});
        const FloatImage ao = s->readRaw("ao.filtered");
        double gpu = 0.0, rays = 0.0;
        for (const auto& [x, y] : region) {
            gpu += ao.at(x, y, 0);
            rays += ref.ao.pixels[static_cast<size_t>(y) * PW + x];
        }
        return std::pair{gpu / region.size(), rays / region.size()};
    };
    const auto [off, truth] = meanAo(false);
    const double atDefault = meanAo(true).first;
    std::printf("wall beside the pole (%zu px): ray-traced %.3f; GTAO %.3f at gtao.thin_occluders=0, %.3f at the default\n",
                region.size(), truth, off, atDefault);
    EXPECT_NEAR(atDefault, truth, 0.03);
    EXPECT_GT(truth - off, 0.1);
}
