#include "renderer/scene/CameraController.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace dw::camera {

namespace {
constexpr float kMaxPitch = glm::half_pi<float>() - glm::radians(1.0f);

// Direction from yaw (about +Y, 0 = towards -Z) and pitch.
glm::vec3 direction(float yaw, float pitch) {
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}
void angles(const glm::vec3& d, float& yaw, float& pitch) {
    const glm::vec3 n = glm::normalize(d);
    pitch = std::asin(std::clamp(n.y, -1.0f, 1.0f));
    yaw = std::atan2(n.x, -n.z);
}
}  // namespace

float distance(const Camera& c) { return glm::length(c.position - c.target); }

void orbit(Camera& c, float yaw, float pitch) {
    const glm::vec3 offset = c.position - c.target;
    const float d = glm::length(offset);
    if (d <= 0.0f) return;
    float y = 0, p = 0;
    angles(offset, y, p);
    y += yaw;
    p = std::clamp(p + pitch, -kMaxPitch, kMaxPitch);
    c.position = c.target + direction(y, p) * d;
    c.up = glm::vec3(0, 1, 0);
}

void zoom(Camera& c, float factor) {
    const glm::vec3 offset = c.position - c.target;
    const float d = glm::length(offset);
    const float next = std::clamp(d * factor, c.nearPlane * 2.0f, c.farPlane * 0.9f);
    if (d > 0.0f) c.position = c.target + offset * (next / d);
}

void pan(Camera& c, float right, float up) {
    const float d = distance(c);
    const glm::vec3 forward = glm::normalize(c.target - c.position);
    const glm::vec3 r = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 u = glm::cross(r, forward);
    const glm::vec3 shift = (r * right + u * up) * d;
    c.position += shift;
    c.target += shift;
}

void fly(Camera& c, const glm::vec3& move) {
    const glm::vec3 forward = glm::normalize(c.target - c.position);
    const glm::vec3 r = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 shift = r * move.x + glm::vec3(0, 1, 0) * move.y + forward * move.z;
    c.position += shift;
    c.target += shift;
}

void look(Camera& c, float yaw, float pitch) {
    const glm::vec3 forward = c.target - c.position;
    const float d = glm::length(forward);
    if (d <= 0.0f) return;
    float y = 0, p = 0;
    angles(forward, y, p);
    // Positive yaw turns right (clockwise seen from above).
    c.target = c.position + direction(y + yaw, std::clamp(p + pitch, -kMaxPitch, kMaxPitch)) * d;
    c.up = glm::vec3(0, 1, 0);
}

}  // namespace dw::camera
