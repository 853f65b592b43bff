// glTF animation (issue 36): each sampler interpolation and channel kind
// against values worked out by hand from the glTF 2.0 spec (Appendix C), and
// skins and morph targets posed through the importer at a scene time.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "renderer/scene/Animation.h"
#include "renderer/scene/GltfLoader.h"
#include "renderer/scene/ScenePose.h"
#include "tests/support/AnimatedGltf.h"
#include "tests/support/GltfBuilder.h"

using namespace dw;

namespace {

AnimationSampler sampler(Interpolation i, std::vector<float> times, std::vector<float> values, int components) {
    AnimationSampler s;
    s.interpolation = i;
    s.times = std::move(times);
    s.values = std::move(values);
    s.components = components;
    return s;
}

}  // namespace

TEST(Animation, StepHoldsTheKeyframeBeforeAndClampsOutsideTheRange) {
    const auto s = sampler(Interpolation::Step, {1, 2, 3}, {10, 20, 30}, 1);
    EXPECT_EQ(sampleAnimation(s, 0.0, false)[0], 10.0f);   // before the first keyframe: the first value
    EXPECT_EQ(sampleAnimation(s, 1.999, false)[0], 10.0f);
    EXPECT_EQ(sampleAnimation(s, 2.0, false)[0], 20.0f);
    EXPECT_EQ(sampleAnimation(s, 2.5, false)[0], 20.0f);
    EXPECT_EQ(sampleAnimation(s, 9.0, false)[0], 30.0f);   // after the last: the last value
}

TEST(Animation, LinearInterpolatesEachComponentAndClamps) {
    const auto s = sampler(Interpolation::Linear, {0, 2}, {0, 10, -4, 2, 20, 4}, 3);
    const auto v = sampleAnimation(s, 0.5, false);  // u = 0.25
    EXPECT_FLOAT_EQ(v[0], 0.5f);
    EXPECT_FLOAT_EQ(v[1], 12.5f);
    EXPECT_FLOAT_EQ(v[2], -2.0f);
    EXPECT_FLOAT_EQ(sampleAnimation(s, -1.0, false)[1], 10.0f);
    EXPECT_FLOAT_EQ(sampleAnimation(s, 3.0, false)[2], 4.0f);
}

TEST(Animation, LinearRotationsSlerpAlongTheShorterArc) {
    // identity to 90 degrees about +Z: at u = 0.5, 45 degrees (not the normalised lerp's angle at u = 0.25).
    const float h = static_cast<float>(std::sqrt(0.5));
    auto s = sampler(Interpolation::Linear, {0, 1}, {0, 0, 0, 1, 0, 0, h, h}, 4);
    const float half = static_cast<float>(M_PI / 8.0);
    auto v = sampleAnimation(s, 0.5, true);
    EXPECT_NEAR(v[2], std::sin(half), 1e-6);
    EXPECT_NEAR(v[3], std::cos(half), 1e-6);
    v = sampleAnimation(s, 0.25, true);  // 22.5 degrees
    EXPECT_NEAR(v[2], std::sin(half / 2), 1e-6);
    EXPECT_NEAR(v[3], std::cos(half / 2), 1e-6);
    // The second key negated (the same rotation): the shorter arc, the same answer up to sign.
    s.values = {0, 0, 0, 1, 0, 0, -h, -h};
    v = sampleAnimation(s, 0.5, true);
    EXPECT_NEAR(std::abs(v[2]), std::sin(half), 1e-6);
    EXPECT_NEAR(std::abs(v[3]), std::cos(half), 1e-6);
    EXPECT_GT(v[2] * v[3], 0.0f);
}

TEST(Animation, CubicSplineIsTheHermiteOfTheSpecWithTangentsScaledByTheInterval) {
    // keys at 0 and 2 s (t_d = 2): (a0, v0, b0) = (0, 1, 2), (a1, v1, b1) = (3, 5, 0).
    const auto s = sampler(Interpolation::CubicSpline, {0, 2}, {0, 1, 2, 3, 5, 0}, 1);
    // t = 0.5: u = 0.25; h00 = 0.84375, h10 = 0.140625, h01 = 0.15625, h11 = -0.046875:
    // 0.84375*1 + 2*0.140625*2 + 0.15625*5 + 2*(-0.046875)*3 = 1.90625.
    EXPECT_FLOAT_EQ(sampleAnimation(s, 0.5, false)[0], 1.90625f);
    EXPECT_FLOAT_EQ(sampleAnimation(s, 0.0, false)[0], 1.0f);  // a value, not a tangent
    EXPECT_FLOAT_EQ(sampleAnimation(s, 5.0, false)[0], 5.0f);
    // A rotation spline comes out normalised.
    const auto q = sampler(Interpolation::CubicSpline, {0, 1}, {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0},
                           4);
    const auto r = sampleAnimation(q, 0.5, true);  // zero tangents: (0, 0, 0.5, 1) normalised
    EXPECT_NEAR(r[2], 0.5 / std::sqrt(1.25), 1e-6);
    EXPECT_NEAR(r[3], 1.0 / std::sqrt(1.25), 1e-6);
}

namespace {

Scene importAnimated(bool withAnimation, const char* name) {
    Scene s;
    importGltf(test::writeJson(name, test::animatedGltf(withAnimation)).string(), s, glm::mat4(1.0f), false);
    return s;
}

// The posed vertex of deformer `d` whose rest position is `rest`.
const Vertex& posed(const Scene& s, int d, const glm::vec3& rest) {
    const Deformer& def = s.animation.deformers[static_cast<std::size_t>(d)];
    for (std::size_t i = 0; i < def.rest.size(); ++i)
        if (def.rest[i].position == rest) return s.meshes[static_cast<std::size_t>(def.mesh)].vertices[i];
    throw std::runtime_error("no such rest vertex");
}

void expectVec3(const glm::vec3& a, const glm::vec3& b, const char* what) {
    EXPECT_NEAR(a.x, b.x, 1e-5) << what;
    EXPECT_NEAR(a.y, b.y, 1e-5) << what;
    EXPECT_NEAR(a.z, b.z, 1e-5) << what;
}

}  // namespace

TEST(Animation, SkinsAndMorphTargetsArePosedAtTheSceneTimeWithNoIgnoredWarning) {
    Scene s = importAnimated(true, "animated.gltf");
    for (const auto& w : s.warnings) EXPECT_EQ(w.find("ignored"), std::string::npos) << w;
    ASSERT_EQ(s.animation.clips.size(), 1u);
    EXPECT_EQ(s.animation.clips[0].name, "move");
    EXPECT_FLOAT_EQ(s.animation.clips[0].end, 1.0f);
    ASSERT_EQ(s.animation.deformers.size(), 2u);
    // t = 0 (the import's pose): the bind pose, morph weight 0 (STEP's first key).
    expectVec3(posed(s, 0, {1, 1, 0}).position, {1, 1, 0}, "bind pose");
    expectVec3(posed(s, 1, {0, 0, 0}).position, {0, 0, 0}, "weight 0");

    ASSERT_TRUE(poseScene(s, 0.5));
    // Root bone at (1,0,0); tip bone at (1,1,0) turned 45 degrees about +Z.
    const float c = static_cast<float>(std::sqrt(0.5));
    expectVec3(posed(s, 0, {0, 0, 0}).position, {1, 0, 0}, "bottom vertex: joint 0 alone");
    expectVec3(posed(s, 0, {0, 1, 0}).position, {1, 1, 0}, "top vertex on the tip's pivot");
    // Half of joint 0 ((2, 1, 0)) and half of joint 1 ((1 + cos 45, 1 + sin 45, 0)).
    expectVec3(posed(s, 0, {1, 1, 0}).position, {1.5f + 0.5f * c, 1.0f + 0.5f * c, 0}, "top vertex blended");
    expectVec3(posed(s, 0, {1, 1, 0}).normal, {0, 0, 1}, "normal about +Z stays");
    // STEP weight 1 from 0.25 s: +1 in z, the normal +Z + (1,0,0) renormalised.
    expectVec3(posed(s, 1, {1, 0, 0}).position, {1, 0, 1}, "morphed");
    expectVec3(posed(s, 1, {1, 0, 0}).normal, {c, 0, c}, "morphed normal");
    // The morphed quad's node places it (3,0,0); the skinned one's node is ignored (glTF 2.0, skins).
    const auto& inst = s.instances;
    ASSERT_EQ(inst.size(), 2u);
    EXPECT_FLOAT_EQ(inst[1].transform[3].x, 3.0f);
    EXPECT_FLOAT_EQ(inst[0].transform[3].x, 0.0f);
    // Past the end the last keys hold: root at (2,0,0), tip turned 90 degrees.
    ASSERT_TRUE(poseScene(s, 7.0));
    expectVec3(posed(s, 0, {1, 1, 0}).position, {2.5f, 1.5f, 0}, "clamped after the end");
    EXPECT_FALSE(poseScene(s, 7.0));  // posed there already
}

TEST(Animation, DefaultMeshWeightsApplyWithoutAnAnimationAndSkinnedNormalsTurn) {
    Scene s = importAnimated(false, "morph-default.gltf");
    ASSERT_EQ(s.animation.deformers.size(), 2u);
    expectVec3(posed(s, 1, {0, 0, 0}).position, {0, 0, 0.25f}, "mesh.weights 0.25");
    // A rotation of the root bone about +Y turns the skinned normals.
    s.animation.nodes[1].rotation = glm::angleAxis(static_cast<float>(M_PI / 2), glm::vec3(0, 1, 0));
    s.animation.posedAt = -1.0;
    poseScene(s, 0.0);
    const Vertex& v = posed(s, 0, {0, 0, 0});
    expectVec3(v.normal, {1, 0, 0}, "normal turned with its joint");
    glm::vec3 restTangent(0.0f);
    for (const Vertex& r : s.animation.deformers[0].rest)
        if (r.position == glm::vec3(0.0f)) restTangent = glm::vec3(r.tangent);
    expectVec3(glm::vec3(v.tangent), s.animation.nodes[1].rotation * restTangent, "tangent turned with its joint");
}

// A broken animation part (an accessor index out of range, an accessor of the
// wrong type) is left out with a warning; the file still loads and the rest plays.
TEST(Animation, BrokenPartsAreLeftOutWithAWarningAndTheRestPlays) {
    auto j = test::animatedGltf();
    j["animations"][0]["samplers"][1]["output"] = 999;                         // rotation sampler: out of range
    j["meshes"][1]["primitives"][0]["targets"][0]["NORMAL"] = 999;             // a target attribute out of range
    j["skins"][0]["inverseBindMatrices"] = j["animations"][0]["samplers"][0]["output"];  // VEC3, not MAT4
    Scene s;
    importGltf(test::writeJson("animation-broken.gltf", j).string(), s, glm::mat4(1.0f), false);
    std::string all;
    for (const auto& w : s.warnings) all += w + "\n";
    EXPECT_NE(all.find("animations[0].channels[1] skipped: sampler accessor out of range"), std::string::npos) << all;
    EXPECT_NE(all.find("(identity used)"), std::string::npos) << all;
    ASSERT_EQ(s.animation.clips.at(0).channels.size(), 2u);  // translation and weights still play
    ASSERT_TRUE(poseScene(s, 0.5));
    expectVec3(posed(s, 1, {1, 0, 0}).position, {1, 0, 1}, "the morph still plays without its NORMAL deltas");
}
