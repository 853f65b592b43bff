#pragma once
// A light as the CMSC 23700 assignment defines it (seed 001, section 3.1):
// name, pos, direction, cutoff (degrees), exponent, intensity RGB and
// attenuation 1/(constant + linear d + quadratic d^2).
#include <glm/glm.hpp>
#include <string>

namespace dw {

enum class LightType { Directional, Point, Spot };

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
    float exponent = 0.0f;                  // spot: (cos theta)^exponent falloff
    glm::vec3 intensity{1.0f};
    Attenuation attenuation;
    bool castShadows = false;
    bool enabled = true;
};

const char* toString(LightType type);

}  // namespace dw
