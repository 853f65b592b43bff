#pragma once
// Flame particles that are themselves point lights (seed 004, "Fire
// Simulation": particles born at the base of a flame rise, sway and shrink as
// they age; "Each Fire is a Point Light"). Every particle's position and
// intensity is a pure function of (particle index, frame index): no wall
// clock and no RNG state, so any frame can be reproduced on its own.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "renderer/scene/Light.h"

namespace dw {

struct Scene;

struct FlameEmitter {
    glm::vec3 base{0.0f};  // centre of the fire bed
    float radius = 0.4f;   // particles are born within this disc
    float height = 1.6f;   // how far a particle rises over its life
    float brightness = 1.0f;
    int particles = 60;
};

// A scene's flame particles: lights [firstLight, firstLight + count()) of
// Scene::lights are the particles, emitter by emitter, each named "flame N".
struct FlameParticles {
    std::vector<FlameEmitter> emitters;
    size_t firstLight = 0;
    int count() const;
    bool empty() const { return emitters.empty(); }
};

struct FlameParticle {
    glm::vec3 position{0.0f};
    glm::vec3 intensity{0.0f};  // fades in at birth and out at death
    float age = 0.0f;           // 0 at birth .. 1 at death (then it respawns)
};

// Particle `index` (0 .. particles-1) of `e` at `frame`; `seed` tells emitters apart.
FlameParticle flameParticle(const FlameEmitter& e, int index, std::uint32_t seed, std::uint64_t frame);
// Every particle of `fire` at `frame`, emitter by emitter.
std::vector<FlameParticle> flameParticles(const FlameParticles& fire, std::uint64_t frame);
// The point lights for `frame` (added after the scene's other lights when built).
void appendFlameLights(const FlameParticles& fire, std::uint64_t frame, std::vector<Light>& lights);
// Moves the scene's particle lights to `frame`. A light is left alone unless it
// is still the particle's ("flame N" at its index), so a list replaced since
// (bench --lights, lights edited in the GUI) is not overwritten. No-op for a
// scene without particles.
void animateFlameParticles(Scene& scene, std::uint64_t frame);

}  // namespace dw
