#include "renderer/scene/Camera.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/Light.h"
#include "renderer/scene/Mesh.h"

namespace dw {

const char* toString(LightType type) {
    switch (type) {
        case LightType::Directional: return "directional";
        case LightType::Point: return "point";
        case LightType::Spot: return "spot";
    }
    return "?";
}

glm::mat4 Camera::view() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
}

namespace {

// Relative to the scene down to this radius: a floor of 1e-3 put the near
// plane of a scene 1e-8 across beyond the whole scene (nothing was drawn).
// Below it a scene is framed as if it were this size (a dot): the camera
// must stay far enough from its look-at point for the float view matrix
// (the squared distance above the smallest float, CameraCheck).
constexpr float kMinFramedRadius = 1e-18f;

}  // namespace

void Camera::fitClipPlanes(const Bounds& bounds) {
    if (bounds.empty()) return;
    const float r = std::max(bounds.radius(), kMinFramedRadius);
    const float d = glm::length(bounds.center() - position);
    // Room to orbit out to about twice the distance, and to move in close:
    // a near plane at a fixed fraction of the far one (1e-3 keeps the 32-bit
    // float depth precise enough for position reconstruction).
    farPlane = d + r * 3.0f;
    nearPlane = farPlane * 1e-3f;
}

Camera Camera::framing(const Bounds& bounds, float fovYDegrees) {
    Camera c;
    c.fovYDegrees = fovYDegrees;
    const glm::vec3 center = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    const float radius = std::max(bounds.radius(), kMinFramedRadius);
    const float distance = radius / std::sin(glm::radians(fovYDegrees) * 0.5f) * 1.1f;
    const glm::vec3 dir = glm::normalize(glm::vec3(0.55f, 0.45f, 1.0f));
    c.target = center;
    c.position = center + dir * distance;
    c.nearPlane = std::max(distance - radius * 1.5f, distance * 0.01f);
    c.farPlane = distance + radius * 3.0f;
    return c;
}

}  // namespace dw
