// Shadow-caster culling's geometry (issue 36, renderer/lighting/CasterCulling):
// boxes placed by hand inside, outside and across a directional light's
// fitted box, a spot's frustum, the faces of a cube map and the halves of a
// dual-paraboloid map, in both depth conventions. A caster between the light
// and a directional map's volume must be kept: it shadows what is inside.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/gl/DepthConvention.h"
#include "renderer/lighting/CasterCulling.h"
#include "renderer/scene/Mesh.h"

using namespace dw;

namespace {

Bounds box(glm::vec3 lo, glm::vec3 hi) {
    Bounds b;
    b.add(lo);
    b.add(hi);
    return b;
}

Bounds around(glm::vec3 c, float r) { return box(c - r, c + r); }

const DepthMode kModes[2] = {DepthMode::Reversed, DepthMode::Conventional};

}  // namespace

// A sun straight down over a box 4 wide (x, z in [-2, 2]) and 10 deep (y in
// [-5, 5]), the eye 10 above the origin as ShadowMaps puts it.
TEST(CasterCulling, DirectionalBoxKeepsCastersTowardsTheLight) {
    for (DepthMode mode : kModes) {
        const DepthConvention dc(mode);
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 10, 0), glm::dvec3(0.0), glm::dvec3(1, 0, 0));
        const glm::dmat4 proj = dc.orthographic(-2.0, 2.0, -2.0, 2.0, 5.0, 15.0);
        const CasterVolume v = CasterVolume::frustum(proj * view, dc.reversed());
        SCOPED_TRACE(dc.reversed() ? "reversed" : "conventional");
        EXPECT_TRUE(v.mayCast(around({0, 0, 0}, 0.5f)));                 // inside
        EXPECT_FALSE(v.mayCast(around({6, 0, 0}, 0.5f)));                // beside it
        EXPECT_FALSE(v.mayCast(around({0, 0, -6}, 0.5f)));               // beside it on the other axis
        EXPECT_TRUE(v.mayCast(box({1.5f, -1, -1}, {3, 1, 1})));          // across its side
        EXPECT_TRUE(v.mayCast(around({0, 8, 0}, 0.5f)));                 // between the light and the box: casts into it
        EXPECT_TRUE(v.mayCast(around({0, 30, 0}, 0.5f)));                // behind the light's eye, still above the box
        EXPECT_FALSE(v.mayCast(around({0, -8, 0}, 0.5f)));               // past the far side
        EXPECT_FALSE(v.mayCast(around({6, 8, 0}, 0.5f)));                // towards the light but beside the box
        EXPECT_TRUE(v.mayCast(box({2, -1, -1}, {3, 1, 1})));             // touching the side exactly
        EXPECT_TRUE(v.mayCast(Bounds{}));                                // an empty box is kept
    }
}

// A spot at (0, 5, 0) pointing down, 60 degrees wide, reaching 20 units.
TEST(CasterCulling, SpotFrustum) {
    for (DepthMode mode : kModes) {
        const DepthConvention dc(mode);
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 5, 0), glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0));
        const glm::dmat4 proj = dc.perspective(glm::radians(60.0), 1.0, 0.02, 20.0);
        const CasterVolume v = CasterVolume::frustum(proj * view, dc.reversed());
        SCOPED_TRACE(dc.reversed() ? "reversed" : "conventional");
        EXPECT_TRUE(v.mayCast(around({0, 0, 0}, 0.5f)));       // in the cone
        EXPECT_FALSE(v.mayCast(around({10, 0, 0}, 0.5f)));     // outside it (tan 30 * 5 = 2.9)
        EXPECT_TRUE(v.mayCast(box({2, -1, -1}, {6, 1, 1})));   // across its edge
        EXPECT_FALSE(v.mayCast(around({0, 8, 0}, 0.5f)));      // behind the light
        EXPECT_TRUE(v.mayCast(around({0, 5, 0}, 0.5f)));       // around the light itself
        EXPECT_FALSE(v.mayCast(around({0, -30, 0}, 0.5f)));    // past its reach
    }
}

// A point light at (1, 2, 3) and GL's six cube faces.
TEST(CasterCulling, CubeFaces) {
    const glm::dvec3 faces[6][2] = {{{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
                                    {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}}};
    const glm::dvec3 light(1, 2, 3);
    const glm::vec3 l(light);
    for (DepthMode mode : kModes) {
        const DepthConvention dc(mode);
        const glm::dmat4 proj = dc.perspective(glm::radians(90.0), 1.0, 0.01, 10.0);
        int inside = 0, across = 0, around = 0;
        for (int f = 0; f < 6; ++f) {
            const CasterVolume v = CasterVolume::frustum(proj * glm::lookAt(light, light + faces[f][0], faces[f][1]),
                                                         dc.reversed());
            const bool onPlusX = v.mayCast(box(l + glm::vec3(2.5f, -0.4f, -0.4f), l + glm::vec3(3.5f, 0.6f, 0.6f)));
            EXPECT_EQ(onPlusX, f == 0) << "face " << f;  // inside +X, outside the other five
            inside += onPlusX;
            // Across the +X / +Y edge: in both faces, no other.
            const bool diagonal = v.mayCast(box(l + glm::vec3(2.0f, 2.0f, -0.3f), l + glm::vec3(3.5f, 3.5f, 0.3f)));
            EXPECT_EQ(diagonal, f == 0 || f == 2) << "face " << f;
            across += diagonal;
            around += v.mayCast(box(l - 0.5f, l + 0.5f));  // around the light: every face
            EXPECT_FALSE(v.mayCast(box(l + glm::vec3(20, -1, -1), l + glm::vec3(21, 1, 1)))) << "past the far plane";
        }
        EXPECT_EQ(inside, 1);
        EXPECT_EQ(across, 2);
        EXPECT_EQ(around, 6);
    }
}

// Two paraboloid halves around a light at (0, 1, 0) with axis +Z, reaching 10.
TEST(CasterCulling, ParaboloidHalves) {
    const glm::dvec3 light(0, 1, 0), axis(0, 0, 1);
    const CasterVolume front = CasterVolume::hemisphere(light, axis, 10.0);
    const CasterVolume back = CasterVolume::hemisphere(light, -axis, 10.0);
    const Bounds ahead = box({-1, 0, 1}, {1, 2, 2}), behind = box({-1, 0, -2}, {1, 2, -1}), across = box({-1, 0, -1}, {1, 2, 1});
    EXPECT_TRUE(front.mayCast(ahead));
    EXPECT_FALSE(back.mayCast(ahead));
    EXPECT_FALSE(front.mayCast(behind));
    EXPECT_TRUE(back.mayCast(behind));
    EXPECT_TRUE(front.mayCast(across));
    EXPECT_TRUE(back.mayCast(across));
    EXPECT_FALSE(front.mayCast(box({-1, 0, 20}, {1, 2, 21})));        // in the half, past the far distance
    EXPECT_TRUE(front.mayCast(box({-1, 0, 0}, {1, 2, 0.5f})));        // touching the dividing plane
    EXPECT_TRUE(back.mayCast(box({-1, 0, 0}, {1, 2, 0.5f})));
    EXPECT_TRUE(front.mayCast(box({9.0f, 1, 1}, {12.0f, 2, 2})));     // across the far sphere
}

// Culling switched off tests nothing.
TEST(CasterCulling, EverythingKeepsEveryBox) {
    EXPECT_TRUE(CasterVolume::everything().mayCast(around({1e6f, 0, 0}, 1.0f)));
    EXPECT_TRUE(CasterVolume::everything().planes().empty());
}
