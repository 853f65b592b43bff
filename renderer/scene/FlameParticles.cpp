#include "renderer/scene/FlameParticles.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <string>

#include "renderer/scene/IntegerHash.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {

std::uint32_t hash(std::uint32_t x) { return hashU32(x); }
// A number in [0, 1) from a few integers.
float rand01(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return static_cast<float>(hash(a * 0x9e3779b9U ^ hash(b * 0x85ebca6bU ^ hash(c + 0x27d4eb2fU))) >> 8) / 16777216.0f;
}

// Flame colour by age: a white-yellow core at birth, orange, then a deep red tip.
glm::vec3 flameColor(float age) {
    const glm::vec3 young(1.0f, 0.78f, 0.38f), mid(1.0f, 0.42f, 0.10f), old(0.75f, 0.12f, 0.03f);
    return age < 0.4f ? glm::mix(young, mid, age / 0.4f) : glm::mix(mid, old, (age - 0.4f) / 0.6f);
}

std::string flameName(size_t n) { return "flame " + std::to_string(n); }

}  // namespace

int FlameParticles::count() const {
    int n = 0;
    for (const auto& e : emitters) n += e.particles;
    return n;
}

FlameParticle flameParticle(const FlameEmitter& e, int index, std::uint32_t seed, std::uint64_t frame) {
    const auto i = static_cast<std::uint32_t>(index);
    // Each particle lives 40..79 frames, out of step with its neighbours.
    const std::uint64_t life = 40 + hash(i * 3U + seed * 7919U) % 40;
    const std::uint64_t offset = hash(i * 5U + 1U + seed * 104729U) % life;
    const std::uint64_t t = frame + offset;
    const auto cycle = static_cast<std::uint32_t>(t / life);  // one life per cycle: a new birth place each time
    const float age = static_cast<float>(t % life) / static_cast<float>(life);

    // Born in the disc (uniform by area), pulled towards the axis as it rises
    // (the tapering tip), pushed by a per-life drift and a sway by frame.
    const float r = e.radius * std::sqrt(rand01(seed, i, cycle * 2U));
    const float a = glm::two_pi<float>() * rand01(seed + 17U, i, cycle * 2U + 1U);
    const glm::vec2 born(std::cos(a) * r, std::sin(a) * r);
    const float da = glm::two_pi<float>() * rand01(seed + 31U, i, cycle);
    const glm::vec2 drift = glm::vec2(std::cos(da), std::sin(da)) * (0.35f * e.radius * rand01(seed + 43U, i, cycle));
    const float f = static_cast<float>(frame % 100000U);
    const float phase = static_cast<float>(i) * 2.399963f;
    const glm::vec2 sway = glm::vec2(std::sin(f * 0.21f + phase), std::cos(f * 0.17f + phase * 1.3f)) * (0.12f * e.radius * age);
    const glm::vec2 xz = born * (1.0f - 0.65f * age) + drift * age + sway;
    const float rise = e.height * (0.85f + 0.3f * rand01(seed + 59U, i, cycle)) * std::pow(age, 0.8f);

    FlameParticle p;
    p.age = age;
    p.position = e.base + glm::vec3(xz.x, rise, xz.y);
    // Fade in over the first tenth of a life, shrink and fade out over the rest.
    const float fadeIn = std::min(age / 0.1f, 1.0f);
    const float fadeOut = std::pow(1.0f - age, 1.5f);
    const float flicker = 0.8f + 0.4f * rand01(seed + 71U, i, static_cast<std::uint32_t>(frame / 3U));
    p.intensity = flameColor(age) * (e.brightness * fadeIn * fadeOut * flicker);
    return p;
}

std::vector<FlameParticle> flameParticles(const FlameParticles& fire, std::uint64_t frame) {
    std::vector<FlameParticle> out;
    out.reserve(static_cast<size_t>(fire.count()));
    for (size_t k = 0; k < fire.emitters.size(); ++k)
        for (int j = 0; j < fire.emitters[k].particles; ++j)
            out.push_back(flameParticle(fire.emitters[k], j, static_cast<std::uint32_t>(k) + 1U, frame));
    return out;
}

void appendFlameLights(const FlameParticles& fire, std::uint64_t frame, std::vector<Light>& lights) {
    const std::vector<FlameParticle> ps = flameParticles(fire, frame);
    for (size_t n = 0; n < ps.size(); ++n) {
        Light l;
        l.type = LightType::Point;
        l.name = flameName(n);
        l.position = ps[n].position;
        l.intensity = ps[n].intensity;
        // Small lights: the quadratic term keeps each one's reach to a few units.
        l.attenuation = {1.0f, 0.0f, 8.0f};
        lights.push_back(std::move(l));
    }
}

void animateFlameParticles(Scene& scene, std::uint64_t frame) {
    const FlameParticles& fire = scene.flames;
    if (fire.empty()) return;
    const std::vector<FlameParticle> ps = flameParticles(fire, frame);
    for (size_t n = 0; n < ps.size(); ++n) {
        const size_t li = fire.firstLight + n;
        if (li >= scene.lights.size()) break;
        Light& l = scene.lights[li];
        if (l.type != LightType::Point || l.name != flameName(n)) continue;
        l.position = ps[n].position;
        l.intensity = ps[n].intensity;
    }
}

}  // namespace dw
