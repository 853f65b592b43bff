#pragma once
// Point lights made from a seed, for `bench --lights N` (seed 000 chapter 6
// measures its strategies against the light count): positions uniform in a
// scene's bounds, lifted slightly above the floor, random but bounded
// colours, and attenuation chosen so that every light's volume radius at the
// lighting threshold (seed 001 eq. 1, solveLightRadius) is the radius asked
// for. The same seed gives the same lights on every machine and compiler:
// std::mt19937's output is fixed by the standard, and the mapping to floats
// is done here, not by std::uniform_real_distribution (implementation-defined).
#include <cstdint>
#include <vector>

#include "renderer/scene/Light.h"
#include "renderer/scene/Mesh.h"

namespace dw {

struct LightGeneratorSettings {
    int count = 100;
    std::uint32_t seed = 1;
    float radius = 3.0f;             // volume radius at `threshold`, scene units
    double threshold = 1.0 / 255.0;  // the value of lighting.threshold the radius is meant for
    float brightness = 1.0f;         // each light's brightest channel
    // Lights start this far above the bounds' floor: a fraction of the bounds'
    // height, at least `minLift` units (a flat scene has no height).
    float liftFraction = 0.05f;
    float minLift = 0.05f;
};

// Throws dw::Error for a negative count, a radius <= 0 or a threshold not
// below the brightness (no light could reach it). An empty `bounds` is the
// unit cube around the origin.
std::vector<Light> generateLights(const Bounds& bounds, const LightGeneratorSettings& settings);

// The quadratic attenuation {1, 0, q} whose radius at `threshold` is `radius`
// for a light whose brightest channel is `brightness`.
Attenuation attenuationForRadius(double radius, double brightness, double threshold);

}  // namespace dw
