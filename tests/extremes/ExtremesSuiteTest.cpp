// The extremes suite (issue 10): scenes and settings at their limits, small.
// For every case, no NaN or infinity in any buffer the frame produced (not
// only `final`: FiniteCheck reads them all back); for the invariance cases
// (offset, scale, depth mode, near/far pairs) the L-buffer stays within a
// stated bound of the same scene at a safe setting. Sizes are 96x54 and
// shadow maps 256 except where a case is about the map, so the whole binary
// stays well inside the CI budget on two cores.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <string>
#include <vector>

#include "renderer/inspect/FiniteCheck.h"
#include "renderer/scene/SceneJsonLoader.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

constexpr int W = 96, H = 54;

// A floor, a box, a sphere, an emissive marker; a shadowing spot, point light
// and sun; ambient (so SSAO runs) and bloom.
Scene baseScene() {
    Scene s = test::planeScene(30.0f);
    s.ambient = glm::vec3(0.08f);
    const int mat = test::addBlinnPhong(s, {0.7f, 0.6f, 0.5f}, glm::vec3(0.3f), 40.0f);
    Material glow;
    glow.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    glow.emissive = glm::vec3(40.0f);
    const int glowMat = s.addMaterial(glow);
    Mesh box = shapes::box({1.0f, 1.5f, 1.0f});
    box.material = mat;
    s.instances.push_back({s.addMesh(std::move(box)), glm::translate(glm::mat4(1.0f), {-1.5f, 0.75f, 0.0f})});
    Mesh ball = shapes::sphere(0.6f);
    ball.material = mat;
    s.instances.push_back({s.addMesh(std::move(ball)), glm::translate(glm::mat4(1.0f), {1.5f, 0.6f, 0.5f})});
    Mesh marker = shapes::sphere(0.1f);
    marker.material = glowMat;
    s.instances.push_back({s.addMesh(std::move(marker)), glm::translate(glm::mat4(1.0f), {0.0f, 2.0f, -1.0f})});
    test::addSpotLight(s, {-1.0f, 4.0f, 2.5f}, {0.2f, -1.0f, -0.6f}, 30.0f, 4.0f, glm::vec3(5.0f), {1.0f, 0.0f, 0.05f})
        .castShadows = true;
    test::addPointLight(s, {2.5f, 2.5f, 1.5f}, glm::vec3(3.0f), {1.0f, 0.0f, 0.1f}).castShadows = true;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.5f, -1.0f, -0.3f));
    sun.intensity = glm::vec3(0.4f);
    sun.castShadows = true;
    s.lights.push_back(sun);
    s.camera.position = {0.0f, 4.0f, 7.0f};
    s.camera.target = {0.0f, 0.5f, 0.0f};
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 100.0f;
    return s;
}

using Knobs = std::vector<std::pair<std::string, std::string>>;

struct Frame {
    FloatImage lbuffer;
    std::vector<NonFiniteCount> counts;
};

Frame renderCase(Scene s, const Knobs& knobs) {
    auto session = test::makeSession(W, H);
    session->setScene(std::move(s));
    session->knobs().setFromString("shadows.map_size", "256");
    for (const auto& [k, v] : knobs) session->knobs().setFromString(k, v);
    session->render({{"final", "gbuffer.view_position", "gbuffer.view_normal"}});
    return {session->readRaw("lbuffer"), FiniteCheck::scan(session->pipeline().outputs())};
}

void expectFinite(const Frame& f, const std::string& what) {
    EXPECT_GE(f.counts.size(), 8u) << what;
    for (const NonFiniteCount& c : f.counts)
        EXPECT_EQ(c.nonFinite(), 0) << what << ": buffer '" << c.buffer << "' holds " << c.nan << " NaN, "
                                    << c.positiveInf << " +Inf, " << c.negativeInf << " -Inf (first at "
                                    << c.firstX << ", " << c.firstY << ")";
}

// Everything scaled by `k` about the origin: positions, sizes, near/far and
// the attenuation's distance terms (linear / k, quadratic / k^2).
void scaleScene(Scene& s, float k) {
    for (auto& i : s.instances) i.transform = glm::scale(glm::mat4(1.0f), glm::vec3(k)) * i.transform;
    for (auto& l : s.lights) {
        l.position *= k;
        l.attenuation.linear /= k;
        l.attenuation.quadratic /= k * k;
    }
    s.camera.position *= k;
    s.camera.target *= k;
    s.camera.nearPlane *= k;
    s.camera.farPlane *= k;
}

void offsetScene(Scene& s, const glm::vec3& o) {
    for (auto& i : s.instances) i.transform[3] += glm::vec4(o, 0.0f);
    for (auto& l : s.lights) l.position += o;
    s.camera.position += o;
    s.camera.target += o;
}

struct ExtremeCase {
    std::string name;
    std::function<void(Scene&)> edit;
    Knobs knobs;
    // Invariance: the safe counterpart (applied to the base scene) and the
    // largest fraction of L-buffer pixels allowed to differ; none if empty.
    std::function<void(Scene&)> safe;
    Knobs safeKnobs;
    double bound = 0.0;
};

std::ostream& operator<<(std::ostream& o, const ExtremeCase& c) { return o << c.name; }

void setAllIntensities(Scene& s, float v) {
    for (auto& l : s.lights) l.intensity = glm::vec3(v);
}

const ExtremeCase kCases[] = {
    // Depth: near/far pairs in both mappings.
    {"near_1e-5_far_1e7_reversed", [](Scene& s) { s.camera.nearPlane = 1e-5f; s.camera.farPlane = 1e7f; }, {},
     [](Scene&) {}, {}, 0.01},
    {"near_1e-5_far_1e7_conventional", [](Scene& s) { s.camera.nearPlane = 1e-5f; s.camera.farPlane = 1e7f; },
     {{"depth.mode", "conventional"}}},
    {"conventional_depth_at_safe_planes", [](Scene&) {}, {{"depth.mode", "conventional"}}, [](Scene&) {}, {}, 0.005},
    {"near_0.05_far_1e6", [](Scene& s) { s.camera.nearPlane = 0.05f; s.camera.farPlane = 1e6f; }, {},
     [](Scene&) {}, {}, 0.01},
    // Intensities.
    {"intensity_0", [](Scene& s) { setAllIntensities(s, 0.0f); }, {}},
    {"intensity_70000", [](Scene& s) { setAllIntensities(s, 70000.0f); }, {}},
    {"intensity_1e20", [](Scene& s) { setAllIntensities(s, 1e20f); }, {}},
    {"intensity_1e20_hdr_add_reinhard", [](Scene& s) { setAllIntensities(s, 1e20f); },
     {{"bloom.composite", "hdr_add"}, {"tonemap.operator", "reinhard"}}},
    {"emission_1e20", [](Scene& s) { s.materials[2].emissive = glm::vec3(1e20f); }, {}},
    // Attenuation.
    {"attenuation_constant_only", [](Scene& s) { for (auto& l : s.lights) l.attenuation = {1.0f, 0.0f, 0.0f}; }, {}},
    {"attenuation_quadratic_light_on_surface",
     [](Scene& s) {
         for (auto& l : s.lights) l.attenuation = {0.0f, 0.0f, 1.0f};
         s.lights[1].position = {1.5f, 0.0f, -1.0f};  // on the floor
     },
     {}},
    {"attenuation_windowed_constant_only", [](Scene& s) { for (auto& l : s.lights) l.attenuation = {1.0f, 0.0f, 0.0f}; },
     {{"lighting.attenuation", "windowed"}}},
    // Spot cones.
    {"cutoff_0.1", [](Scene& s) { s.lights[0].cutoffDegrees = 0.1f; }, {}},
    {"cutoff_89.9", [](Scene& s) { s.lights[0].cutoffDegrees = 89.9f; }, {}},
    {"cutoff_89.9_paraboloid", [](Scene& s) { s.lights[0].cutoffDegrees = 89.9f; },
     {{"shadows.point_method", "dual_paraboloid"}}},
    // Camera inside a light volume and at a light.
    {"camera_inside_volumes", [](Scene& s) { s.camera.position = {2.0f, 2.0f, 1.0f}; s.camera.target = {0.0f, 0.5f, -1.0f}; },
     {}},
    {"camera_at_point_light", [](Scene& s) { s.camera.position = s.lights[1].position; }, {}},
    {"camera_at_spot_light", [](Scene& s) { s.camera.position = s.lights[0].position; }, {}},
    {"point_light_inside_box", [](Scene& s) { s.lights[1].position = {-1.5f, 0.75f, 0.0f}; }, {}},
    // Scales (ambient off: the SSAO radius is in world units).
    {"scale_1e-4", [](Scene& s) { s.ambient = glm::vec3(0.0f); scaleScene(s, 1e-4f); }, {},
     [](Scene& s) { s.ambient = glm::vec3(0.0f); }, {}, 0.01},
    {"scale_1e4", [](Scene& s) { s.ambient = glm::vec3(0.0f); scaleScene(s, 1e4f); }, {},
     [](Scene& s) { s.ambient = glm::vec3(0.0f); }, {}, 0.01},
    // Offsets from the world origin.
    {"offset_1e5", [](Scene& s) { offsetScene(s, {1e5f, 0.0f, -1e5f}); }, {}, [](Scene&) {}, {}, 0.005},
    // At 1e6 float instance transforms resolve 1/16: the sphere at y = 0.6
    // sits at 0.625, so its silhouette moves by a fraction of a pixel.
    {"offset_1e6", [](Scene& s) { offsetScene(s, {1e6f, 1e6f, 1e6f}); }, {}, [](Scene&) {}, {}, 0.02},
    {"offset_1e6_tiled", [](Scene& s) { offsetScene(s, {-1e6f, 0.0f, 1e6f}); }, {{"lighting.strategy", "tiled"}},
     [](Scene&) {}, {{"lighting.strategy", "tiled"}}, 0.005},
    {"offset_1e6_forward", [](Scene& s) { offsetScene(s, {-1e6f, 0.0f, 1e6f}); }, {{"lighting.strategy", "forward"}},
     [](Scene&) {}, {{"lighting.strategy", "forward"}}, 0.005},
    // Empty views and degenerate geometry.
    {"only_sky_background_excluded", [](Scene& s) { s.camera.target = s.camera.position + glm::vec3(0.0f, 1.0f, 0.01f); },
     {{"luminance.background", "exclude"}}},
    {"degenerate_triangles_zero_normals",
     [](Scene& s) {
         Mesh m;
         m.name = "degenerate";
         Vertex a, b, c, d;
         a.position = {0.0f, 0.5f, 1.5f};
         b.position = {0.0f, 0.5f, 1.5f};  // a zero-area triangle
         c.position = {0.5f, 0.5f, 1.5f};
         d.position = {0.0f, 1.0f, 1.5f};
         for (Vertex* v : {&a, &b, &c, &d}) v->normal = glm::vec3(0.0f);  // zero normals
         m.vertices = {a, b, c, d};
         m.indices = {0, 1, 2, 0, 2, 3, 2, 2, 2};
         m.material = 1;
         m.computeBounds();
         s.instances.push_back({s.addMesh(std::move(m)), glm::mat4(1.0f)});
     },
     {}},
};

}  // namespace

class Extremes : public ::testing::TestWithParam<ExtremeCase> {};

TEST_P(Extremes, EveryBufferFiniteAndInvariantsHold) {
    const ExtremeCase& c = GetParam();
    Scene s = baseScene();
    c.edit(s);
    const Frame f = renderCase(std::move(s), c.knobs);
    expectFinite(f, c.name);
    if (c.safe) {
        Scene safe = baseScene();
        c.safe(safe);
        const Frame ref = renderCase(std::move(safe), c.safeKnobs);
        const double off = test::fractionOff(ref.lbuffer, f.lbuffer);
        std::printf("%s: %.3f%% of L-buffer pixels off by > 2%% from the safe setting (bound %.1f%%)\n", c.name.c_str(),
                    100.0 * off, 100.0 * c.bound);
        EXPECT_LE(off, c.bound) << c.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, Extremes, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<ExtremeCase>& p) {
                             std::string n = p.param.name;
                             for (char& ch : n)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return n;
                         });

// Every knob at its minimum and maximum (each choice of an enum, both values
// of a switch): every produced buffer stays finite. shadows.map_size's
// maximum is rendered with the sun as the only shadow caster (a 4096^2 2D
// map; six such cube faces per light would be 400 MB for nothing).
TEST(Extremes, EveryKnobAtItsMinimumAndMaximumRendersFinite) {
    auto session = test::makeSession(64, 36);
    session->setScene(baseScene());
    KnobRegistry& k = session->knobs();
    int renders = 0;
    for (std::size_t id = 0; id < k.specs().size(); ++id) {
        const KnobSpec spec = k.specs()[id];
        std::vector<double> values;
        if (spec.type == KnobType::Enum)
            for (std::size_t i = 0; i < spec.choices.size(); ++i) values.push_back(static_cast<double>(i));
        else
            values = {spec.minValue, spec.maxValue};
        const double before = k.value(static_cast<int>(id));
        for (double v : values) {
            if (spec.name == "shadows.map_size" && v > 1024) continue;  // below, with the sun alone
            k.set(static_cast<int>(id), v);
            session->render({{"final"}});
            ++renders;
            for (const NonFiniteCount& c : FiniteCheck::scan(session->pipeline().outputs()))
                EXPECT_EQ(c.nonFinite(), 0) << spec.name << " = " << k.formatValue(static_cast<int>(id), v) << ": buffer '"
                                            << c.buffer << "' holds " << c.nonFinite() << " non-finite values";
        }
        k.set(static_cast<int>(id), before);
    }
    std::printf("%d renders over %zu knobs\n", renders, k.specs().size());
    EXPECT_GT(renders, 100);
    Scene sunOnly = baseScene();
    for (auto& l : sunOnly.lights) l.castShadows = l.type == LightType::Directional;
    const Frame f = renderCase(std::move(sunOnly), {{"shadows.map_size", "4096"}});
    expectFinite(f, "shadows.map_size = 4096");
}

// Environment maps full of NaN, infinities, negative and huge values,
// written small into the test's directory and loaded through a scene file:
// sanitised at load with a warning, and every buffer finite.
TEST(Extremes, NanAndInfinityEnvironmentMapsAreSanitisedAtLoad) {
    const int ew = 16, eh = 8;
    FloatImage env{ew, eh, 3, std::vector<float>(static_cast<std::size_t>(ew) * eh * 3, 1.0f)};
    const float specials[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(), -5.0f, 1e30f, 65504.0f, 70000.0f};
    for (std::size_t i = 0; i < env.pixels.size(); i += 3) env.pixels[i] = specials[(i / 3) % 7];
    const fs::path dir = test::tempDir();
    writeImage((dir / "bad_env.exr").string(), env);
    const fs::path json = dir / "bad_env.json";
    std::ofstream(json) << R"({ "camera": { "pos": [0, 2, 6], "look-at": [0, 1, 0] }, "ambient": [0.1, 0.1, 0.1],
        "sky": { "type": "environment", "file": "bad_env.exr" },
        "objects": [ { "shape": "sphere", "radius": 1, "pos": [0, 1, 0], "material": { "diffuse": [0.8, 0.8, 0.8] } } ] })";
    Scene s = loadSceneJson(json.string());
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_NE(s.warnings.back().find("values were NaN"), std::string::npos) << s.warnings.back();
    for (const char* mode : {"scene", "environment"}) {
        const Frame f = renderCase(s, {{"skybox.mode", mode}, {"tonemap.nan_guard", "false"}});
        expectFinite(f, std::string("environment with NaN/Inf, skybox.mode ") + mode);
    }
}

// The shared HDR test images (../shared/data/hdr), when present.
TEST(Extremes, SharedHdrTestImagesRenderFinite) {
    const fs::path hdr = test::dataDir() / "hdr";
    if (!fs::exists(hdr)) GTEST_SKIP() << hdr << " is not here";
    int n = 0;
    // (WideFloatRange.exr has one channel: the loader rejects it with a message, as it should.)
    for (const char* name : {"BrightRingsNanInf.exr", "AllHalfValues.exr"}) {
        if (!fs::exists(hdr / name)) continue;
        const fs::path json = test::tempDir() / (std::string(name) + ".json");
        std::ofstream(json) << R"({ "camera": { "pos": [0, 2, 6], "look-at": [0, 1, 0] }, "ambient": [0.1, 0.1, 0.1],
            "sky": { "type": "environment", "file": ")" << (hdr / name).string() << R"(" },
            "objects": [ { "shape": "sphere", "radius": 1, "pos": [0, 1, 0], "material": { "diffuse": [0.8, 0.8, 0.8] } } ] })";
        expectFinite(renderCase(loadSceneJson(json.string()), {{"tonemap.nan_guard", "false"}}), name);
        ++n;
    }
    EXPECT_GT(n, 0);
}

// The key-based Reinhard operator (seed 000 eqs. 4.1-4.4, the default)
// divides by the log-average luminance, so one scene lit 1e8, 1e16 or 1e20
// times brighter tone-maps to the same image. Lights without a radius (a sun
// and the ambient term) keep the scene itself unchanged by the scale
// (emission is left out: the G-buffer stores it in R11G11B10F). Until the NaN guard stopped clamping at the half-float maximum
// (65504, from when the L-buffer was RGBA16F), a scene at 1e16 came out
// black.
TEST(Extremes, ReinhardGivesTheSameImageWhateverTheIntensityScale) {
    auto frameAt = [](float k) {
        Scene s = baseScene();
        s.lights.erase(std::remove_if(s.lights.begin(), s.lights.end(),
                                      [](const Light& l) { return l.type != LightType::Directional; }),
                       s.lights.end());
        for (Light& l : s.lights) l.intensity *= k;
        s.ambient *= k;
        for (Material& m : s.materials) m.emissive = glm::vec3(0.0f);  // stored as R11G11B10F: at most 65000
        auto session = test::makeSession(W, H);
        session->setScene(std::move(s));
        for (const auto& [knob, value] : Knobs{{"shadows.map_size", "256"}, {"skybox.mode", "color"},
                                              {"luminance.background", "exclude"}, {"tonemap.operator", "reinhard"}})
            session->knobs().setFromString(knob, value);
        session->render({{"final"}});
        return session->readRaw("final");
    };
    const FloatImage reference = frameAt(1.0f);
    EXPECT_GT(test::stats(reference, 0).mean, 0.05);
    for (const float k : {1e8f, 1e16f, 1e20f}) {
        const FloatImage image = frameAt(k);
        const double off = test::fractionOff(image, reference);
        std::printf("Reinhard at intensity x %.0e: mean %.3f (x1: %.3f), %.4f%% of pixels off by more than 2%%\n", k,
                    test::stats(image, 0).mean, test::stats(reference, 0).mean, 100.0 * off);
        EXPECT_LT(off, 0.01) << k;
    }
}
