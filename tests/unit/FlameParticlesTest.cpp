// The fire scene's flame particles (seed 004): point lights whose positions and
// intensities are a pure function of (particle index, frame index).
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/scene/BuiltinScenes.h"
#include "renderer/scene/FlameParticles.h"

using namespace dw;

namespace {
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

TEST(FlameParticles, TheFireSceneHasHundredsOfParticleLights) {
    const Scene s = makeBuiltinScene("fire");
    const int n = s.flames.count();
    EXPECT_GE(n, 200);
    EXPECT_LT(n, 1000);
    ASSERT_EQ(s.lights.size(), s.flames.firstLight + static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const Light& l = s.lights[s.flames.firstLight + i];
        EXPECT_EQ(l.type, LightType::Point);
        EXPECT_EQ(l.name, "flame " + std::to_string(i));
    }
}

TEST(FlameParticles, AFrameIsReproducibleFiniteAndInsideTheScene) {
    const Scene s = makeBuiltinScene("fire");
    Bounds box = s.bounds();
    for (std::uint64_t frame : {0ull, 1ull, 7ull, 60ull, 1000ull, 123456789ull}) {
        const auto a = flameParticles(s.flames, frame);
        const auto b = flameParticles(s.flames, frame);
        ASSERT_EQ(a.size(), static_cast<size_t>(s.flames.count()));
        for (size_t i = 0; i < a.size(); ++i) {
            EXPECT_EQ(a[i].position, b[i].position);
            EXPECT_EQ(a[i].intensity, b[i].intensity);
            ASSERT_TRUE(finite(a[i].position) && finite(a[i].intensity)) << i << " @ " << frame;
            EXPECT_GE(a[i].age, 0.0f);
            EXPECT_LT(a[i].age, 1.0f);
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(a[i].intensity[k], 0.0f);
                EXPECT_LT(a[i].intensity[k], 4.0f);
                EXPECT_GE(a[i].position[k], box.min[k]) << i << " @ " << frame;
                EXPECT_LE(a[i].position[k], box.max[k]) << i << " @ " << frame;
            }
        }
    }
}

TEST(FlameParticles, ParticlesMoveBetweenFramesAndEachFrameStandsAlone) {
    Scene s = makeBuiltinScene("fire");
    const auto f0 = flameParticles(s.flames, 10);
    const auto f1 = flameParticles(s.flames, 11);
    int moved = 0, changed = 0;
    for (size_t i = 0; i < f0.size(); ++i) {
        if (f0[i].position != f1[i].position) ++moved;
        if (f0[i].intensity != f1[i].intensity) ++changed;
    }
    EXPECT_EQ(moved, static_cast<int>(f0.size()));
    EXPECT_GT(changed, static_cast<int>(f0.size()) * 9 / 10);
    // Particles respawn: over a few lifetimes every particle is reborn low down.
    bool reborn = false;
    for (std::uint64_t f = 0; f < 200 && !reborn; ++f) reborn = flameParticles(s.flames, f)[0].age < 0.05f;
    EXPECT_TRUE(reborn);

    // Animating jumps straight to a frame: no history.
    animateFlameParticles(s, 3);
    animateFlameParticles(s, 42);
    Scene fresh = makeBuiltinScene("fire");
    animateFlameParticles(fresh, 42);
    for (size_t i = 0; i < s.lights.size(); ++i) {
        EXPECT_EQ(s.lights[i].position, fresh.lights[i].position);
        EXPECT_EQ(s.lights[i].intensity, fresh.lights[i].intensity);
    }
    const auto f42 = flameParticles(s.flames, 42);
    EXPECT_EQ(s.lights[s.flames.firstLight + 5].position, f42[5].position);
}

TEST(FlameParticles, LightsThatAreNoLongerTheParticlesAreLeftAlone) {
    Scene s = makeBuiltinScene("fire");
    // What bench --lights does: the list replaced by other lights.
    std::vector<Light> other(s.lights.size());
    for (size_t i = 0; i < other.size(); ++i) other[i].name = "generated " + std::to_string(i);
    s.lights = other;
    animateFlameParticles(s, 9);
    for (const auto& l : s.lights) EXPECT_EQ(l.position, glm::vec3(0.0f));
    // A scene without particles is untouched.
    Scene d = makeBuiltinScene("default");
    const auto before = d.lights;
    animateFlameParticles(d, 9);
    for (size_t i = 0; i < d.lights.size(); ++i) EXPECT_EQ(d.lights[i].position, before[i].position);
}
