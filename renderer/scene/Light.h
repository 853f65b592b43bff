#pragma once
// A light as the CMSC 23700 assignment defines it (seed 001, section 3.1):
// name, pos, direction, cutoff (degrees), exponent, intensity RGB and
// attenuation 1/(constant + linear d + quadratic d^2); a spot light imported
// from glTF keeps the cone of KHR_lights_punctual instead of the exponent.
#include <glm/glm.hpp>
#include <string>

namespace dw {

enum class LightType { Directional, Point, Spot };

// How a spot light's intensity falls off towards the edge of its cone, whose
// half-angle is cutoffDegrees in both models (so volumes, culling and shadow
// maps are the same for both).
enum class SpotFalloff {
    // Seed 001 section 3.3: (cos theta)^exponent inside the cutoff, 0 outside.
    CutoffExponent,
    // KHR_lights_punctual: 1 inside innerConeDegrees, t^2 with
    // t = (cos theta - cos outer) / (cos inner - cos outer) between the cones,
    // 0 at the outer cone (cutoffDegrees) and beyond.
    InnerOuterCone,
};

struct Attenuation {
    float constant = 1.0f;
    float linear = 0.0f;
    float quadratic = 0.0f;
};

struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // where the light points (spot, directional)
    float cutoffDegrees = 45.0f;            // spot: angle between axis and cone edge
    float exponent = 0.0f;                  // spot: (cos theta)^exponent falloff (CutoffExponent)
    SpotFalloff falloff = SpotFalloff::CutoffExponent;
    float innerConeDegrees = 0.0f;          // spot: full intensity inside (InnerOuterCone), <= cutoffDegrees
    glm::vec3 intensity{1.0f};
    Attenuation attenuation;
    bool castShadows = false;
    bool enabled = true;
};

const char* toString(LightType type);

}  // namespace dw
