#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <limits>
#include <random>

#include "renderer/lighting/LightVolume.h"

using namespace dw;

namespace {
// I_max * att(r) relative to the threshold: 1 at the solved radius.
double ratioAtRadius(const Attenuation& a, double imax, double t, double r) {
    return imax / (a.constant + a.linear * r + a.quadratic * r * r) / t;
}
}  // namespace

TEST(LightRadius, SeedExampleGivesAbout29) {
    // Seed 001 section 2.2: a = 0.3, b = 0, c = 0, I = 1 at 1/255 -> d ~ 29.
    const double r = solveLightRadius({0.0f, 0.0f, 0.3f}, 1.0, 1.0 / 255.0);
    EXPECT_NEAR(r, std::sqrt(255.0 / static_cast<double>(0.3f)), 1e-9);
    EXPECT_NEAR(r, 29.15, 0.01);
}

TEST(LightRadius, LinearOnlyAttenuation) {
    // a = 0: the quadratic formula of seed 001 divides by zero; the stable form does not.
    const double r = solveLightRadius({1.0f, 0.5f, 0.0f}, 2.0, 1.0 / 255.0);
    EXPECT_NEAR(r, (510.0 - 1.0) / 0.5, 1e-9);
}

TEST(LightRadius, TinyQuadraticTermHasNoCancellation) {
    const Attenuation a{1.0f, 1.0f, 1e-14f};
    const double r = solveLightRadius(a, 1.0, 1.0 / 255.0);
    EXPECT_NEAR(ratioAtRadius(a, 1.0, 1.0 / 255.0, r), 1.0, 1e-9);
    // The textbook form (-b + sqrt(b^2 - 4a(c - k))) / 2a loses most digits here.
    const double k = 255.0, qa = static_cast<double>(1e-14f);
    const double naive = (-1.0 + std::sqrt(1.0 - 4.0 * qa * (1.0 - k))) / (2.0 * qa);
    EXPECT_GT(std::fabs(ratioAtRadius(a, 1.0, 1.0 / 255.0, naive) - 1.0), 1e-6);
}

TEST(LightRadius, HugeAndTinyIntensities) {
    const Attenuation a{1.0f, 0.1f, 0.5f};
    const double big = solveLightRadius(a, 1e12, 1.0 / 255.0);
    EXPECT_TRUE(std::isfinite(big));
    EXPECT_NEAR(ratioAtRadius(a, 1e12, 1.0 / 255.0, big), 1.0, 1e-9);
    // Never brighter than the threshold: no volume at all.
    EXPECT_EQ(solveLightRadius(a, 1e-3, 1.0 / 255.0), 0.0);
    EXPECT_EQ(solveLightRadius(a, 0.0, 1.0 / 255.0), 0.0);
    // Constant attenuation never falls off: unbounded.
    EXPECT_TRUE(std::isinf(solveLightRadius({1.0f, 0.0f, 0.0f}, 1.0, 1.0 / 255.0)));
}

TEST(LightRadius, RandomAttenuationsHitTheThresholdExactly) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const Attenuation a{static_cast<float>(u(rng) * 2.0), static_cast<float>(u(rng) * 3.0),
                            static_cast<float>(std::pow(10.0, -6.0 + 8.0 * u(rng)))};
        const double imax = std::pow(10.0, -2.0 + 6.0 * u(rng));
        const double t = std::pow(10.0, -5.0 + 4.0 * u(rng));
        const double r = solveLightRadius(a, imax, t);
        if (imax / t <= a.constant) {
            EXPECT_EQ(r, 0.0);
            continue;
        }
        ASSERT_TRUE(std::isfinite(r));
        EXPECT_NEAR(ratioAtRadius(a, imax, t, r), 1.0, 1e-7) << i;
    }
}

TEST(LightVolumeMesh, SphereEnclosesTheLitBallAndIsTight) {
    Light l;
    l.type = LightType::Point;
    l.position = {3.0f, -1.0f, 2.0f};
    l.intensity = glm::vec3(5.0f);
    l.attenuation = {1.0f, 0.2f, 0.4f};
    const LightVolume v = computeLightVolume(l, 1.0 / 255.0);
    ASSERT_EQ(v.shape, VolumeShape::Sphere);
    const auto r = static_cast<float>(v.radius);
    std::mt19937 rng(1);
    std::normal_distribution<float> n;
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    // Every mesh lighting.volume_subdivisions offers (20 to 1280 faces).
    const float loosest[] = {1.26f, 1.075f, 1.02f, 1.005f};
    for (int k = 0; k <= kMaxSphereSubdivisions; ++k) {
        const VolumeMesh& mesh = unitSphereVolume(k);
        EXPECT_EQ(mesh.indices.size(), 3u * 20u << (2 * k));
        for (int i = 0; i < 5000; ++i) {
            const glm::vec3 dir = glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
            // Points in the lit ball, many right on its boundary.
            const float d = i % 2 ? r : r * std::cbrt(u(rng));
            EXPECT_TRUE(mesh.contains(v.transform, l.position + dir * d)) << "k " << k << ", point " << i << " at distance " << d;
        }
        // And not absurdly loose: every vertex within the icosphere's circumradius.
        for (const auto& p : mesh.positions) EXPECT_LT(glm::length(p), loosest[k]) << "k " << k;
    }
}

TEST(LightVolumeMesh, ConeEnclosesTheLitSectorForManyCutoffs) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::normal_distribution<float> n;
    const VolumeMesh& cone = unitConeVolume();
    for (float cutoff : {5.0f, 15.0f, 30.0f, 45.0f, 60.0f, 63.0f}) {
        Light l;
        l.type = LightType::Spot;
        l.position = {-2.0f, 4.0f, 1.0f};
        l.direction = glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
        l.cutoffDegrees = cutoff;
        l.intensity = glm::vec3(3.0f);
        l.attenuation = {1.0f, 0.0f, 1.0f};
        const LightVolume v = computeLightVolume(l, 1.0 / 255.0);
        ASSERT_EQ(v.shape, VolumeShape::Cone) << cutoff;
        const auto r = static_cast<float>(v.radius);
        const float cosCut = std::cos(glm::radians(cutoff));
        int tested = 0;
        while (tested < 3000) {
            // Rejection-sample the spherical sector {|p| <= r, angle <= cutoff}.
            const glm::vec3 dir = glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
            if (glm::dot(dir, l.direction) < cosCut) continue;
            const float d = tested % 3 == 0 ? r : r * std::cbrt(u(rng));
            EXPECT_TRUE(cone.contains(v.transform, l.position + dir * d)) << "cutoff " << cutoff << " point " << tested;
            ++tested;
        }
        // The cone's rim and the sector's edge at the cutoff angle.
        const glm::vec3 side = glm::normalize(glm::cross(l.direction, glm::vec3(0.3f, 1.0f, 0.2f)));
        const glm::vec3 edge = glm::normalize(l.direction * cosCut + side * std::sin(glm::radians(cutoff)));
        EXPECT_TRUE(cone.contains(v.transform, l.position + edge * r));
    }
}

TEST(LightVolumeMesh, WideSpotsUseTheSphereAndDirectionalLightsAreFullScreen) {
    Light spot;
    spot.type = LightType::Spot;
    spot.cutoffDegrees = 80.0f;
    spot.attenuation = {1.0f, 0.0f, 1.0f};
    EXPECT_EQ(computeLightVolume(spot, 1.0 / 255.0).shape, VolumeShape::Sphere);
    Light sun;
    sun.type = LightType::Directional;
    EXPECT_EQ(computeLightVolume(sun, 1.0 / 255.0).shape, VolumeShape::FullScreen);
    Light constant;
    constant.attenuation = {1.0f, 0.0f, 0.0f};
    EXPECT_EQ(computeLightVolume(constant, 1.0 / 255.0).shape, VolumeShape::FullScreen);
    Light off;
    off.enabled = false;
    EXPECT_EQ(computeLightVolume(off, 1.0 / 255.0).shape, VolumeShape::Culled);
}

// The probe's "lights at this pixel": the point and spot lights whose volume
// mesh contains the surface point, as the stencil test would find them.
TEST(LightVolume, LightsCoveringAPointAreThoseWhoseVolumeMeshContainsIt) {
    std::vector<Light> lights(5);
    for (auto& l : lights) l.attenuation = {1.0f, 0.0f, 1.0f};  // radius sqrt(255) - ... at 1/255
    lights[0].position = {0, 0, 0};
    lights[1].position = {100, 0, 0};  // far away
    lights[2].position = {3, 0, 0};
    lights[2].enabled = false;         // off: never listed
    lights[3].type = LightType::Directional;
    lights[4].type = LightType::Spot;
    lights[4].position = {0, 5, 0};
    lights[4].direction = {0, -1, 0};
    lights[4].cutoffDegrees = 20.0f;
    const glm::vec3 p(1.0f, 0.0f, 0.0f);
    const double threshold = 1.0 / 255.0;
    ASSERT_GT(computeLightVolume(lights[0], threshold).radius, 5.0);
    EXPECT_EQ(lightsCovering(lights, p, threshold), (std::vector<int>{0, 4}));
    // Outside the spot's cone: not listed.
    EXPECT_EQ(lightsCovering(lights, glm::vec3(6.0f, 0.0f, 0.0f), threshold), (std::vector<int>{0}));
    // A higher threshold shrinks the volumes until none contains the point.
    EXPECT_TRUE(lightsCovering(lights, glm::vec3(4.0f, 3.0f, 0.0f), 0.2).empty());
}
