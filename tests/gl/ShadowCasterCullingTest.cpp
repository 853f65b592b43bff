// Shadow-caster culling (issue 36): with shadows.cull_casters on, each shadow
// map draws only the draws whose box meets its volume, and the images are
// bit-identical to drawing every caster into every map: the final image and
// the L-buffer, on every built-in scene, a glTF file, and the other map
// kinds (dual paraboloids, every map kept, blended casters). The shadow
// pass's statistics line counts the casters drawn over those without culling.
#include <gtest/gtest.h>

#include <cstring>
#include <regex>

#include "renderer/scene/BuiltinScenes.h"
#include "tests/support/AnimatedGltf.h"
#include "tests/support/GltfBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

struct Frame {
    FloatImage final, lbuffer;
    std::string shadowStats;
};

// A fresh session each time: the fire scene moves its particles by the
// session's frame count.
Frame renderWith(const std::string& scene, bool cull, const std::vector<std::string>& knobs, double sceneTime = 0.0) {
    auto session = test::makeSession(96, 54);
    RenderSession& s = *session;
    s.loadScene(scene);
    s.setSceneTime(sceneTime);
    for (const std::string& kv : knobs) {
        const auto eq = kv.find('=');
        s.knobs().setFromString(kv.substr(0, eq), kv.substr(eq + 1));
    }
    s.knobs().setFromString("shadows.cull_casters", cull ? "true" : "false");
    const FrameReport r = s.render({{"final", "lbuffer"}});
    Frame f{s.readRaw("final"), s.readRaw("lbuffer"), {}};
    if (const PassRecord* p = r.find("shadows"); p && p->ran) f.shadowStats = p->stats;
    return f;
}

bool identical(const FloatImage& a, const FloatImage& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// "casters D/N" of the shadow pass's line: {D, N}, or {-1, -1}.
std::pair<long, long> casters(const std::string& stats) {
    std::smatch m;
    if (!std::regex_search(stats, m, std::regex("casters (\\d+)/(\\d+), (\\d+)/(\\d+) triangles"))) return {-1, -1};
    return {std::stol(m[1]), std::stol(m[2])};
}

// Renders `scene` both ways and expects the same bits; returns both lines.
std::pair<std::string, std::string> expectIdentical(const std::string& scene, const std::vector<std::string>& knobs = {},
                                                    double sceneTime = 0.0) {
    const Frame off = renderWith(scene, false, knobs, sceneTime);
    const Frame on = renderWith(scene, true, knobs, sceneTime);
    EXPECT_TRUE(identical(off.final, on.final)) << scene << ": final differs with shadows.cull_casters";
    EXPECT_TRUE(identical(off.lbuffer, on.lbuffer)) << scene << ": lbuffer differs with shadows.cull_casters";
    const auto [dOff, nOff] = casters(off.shadowStats);
    const auto [dOn, nOn] = casters(on.shadowStats);
    EXPECT_EQ(dOff, nOff) << scene << ": without culling every caster is drawn: " << off.shadowStats;
    EXPECT_EQ(nOn, nOff) << scene << ": the same maps either way";
    EXPECT_LE(dOn, nOn) << on.shadowStats;
    return {off.shadowStats, on.shadowStats};
}

}  // namespace

TEST(ShadowCasterCulling, EveryBuiltinSceneIsBitIdentical) {
    for (const BuiltinSceneInfo& info : builtinScenes()) {
        SCOPED_TRACE(info.name);
        expectIdentical(info.name);
    }
}

// spheres has a shadowed point light (a cube map, or two paraboloids); glass
// blended casters.
TEST(ShadowCasterCulling, OtherMapKindsAreBitIdentical) {
    const auto paraboloid = expectIdentical("spheres", {"shadows.point_method=dual_paraboloid"}).second;
    EXPECT_NE(paraboloid.find("1 paraboloid"), std::string::npos) << paraboloid;
    EXPECT_LT(casters(paraboloid).first, casters(paraboloid).second) << paraboloid;
    const auto cube = expectIdentical("spheres", {"shadows.reuse_map=false"}).second;
    EXPECT_NE(cube.find("1 cube"), std::string::npos) << cube;
    EXPECT_LT(casters(cube).first, casters(cube).second) << cube;
    expectIdentical("default", {"shadows.reuse_map=false", "shadows.blended_casters=true"});
    expectIdentical("glass", {"shadows.blended_casters=true"});
}

// A glTF file (no lights of its own: the default rig's shadowed sun).
TEST(ShadowCasterCulling, GltfIsBitIdentical) {
    const auto [off, on] = expectIdentical(std::string(DW_TEST_GLTF_DIR) + "/split_corner_tangents.gltf");
    EXPECT_GT(casters(on).second, 0) << on;
}

// Issue 36: an animated glTF posed at 0.5 s: each draw's box is the posed
// one (the skinned quad moved from x <= 1 to x <= 2), and culling
// against those boxes is bit-identical to drawing every caster.
TEST(ShadowCasterCulling, AnimatedGltfCullsAgainstThePosedBoxes) {
    const std::string scene = test::writeJson("culling-animated.gltf", test::animatedGltf()).string();
    auto session = test::makeSession(96, 54);
    session->loadScene(scene);
    auto maxX = [&] {
        float x = -1e30f;
        for (const GpuScene::Draw& d : session->pipeline().gpuScene().draws())
            if (d.mesh == session->scene().animation.deformers.at(0).mesh) x = d.bounds.max.x;
        return x;
    };
    EXPECT_NEAR(maxX(), 1.0f, 1e-5);
    session->setSceneTime(0.5);
    session->render({{"final"}});
    EXPECT_NEAR(maxX(), 2.0f, 1e-5);  // the vertex (1, 0, 0) on the root bone, moved by (1, 0, 0)
    const auto [off, on] = expectIdentical(scene, {}, 0.5);
    EXPECT_GT(casters(on).second, 0) << on;
}

// street's spot lamps each see a few houses, default's lights a part of the
// courtyard: culling draws fewer casters there.
TEST(ShadowCasterCulling, StreetAndDefaultDrawFewerCasters) {
    for (const char* scene : {"street", "default"}) {
        const auto [off, on] = expectIdentical(scene);
        const auto [d, n] = casters(on);
        EXPECT_GT(n, 0) << scene << ": " << on;
        EXPECT_LT(d, n) << scene << ": " << on;
        EXPECT_NE(on.find("triangles"), std::string::npos) << on;
    }
}
