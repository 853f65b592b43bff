#pragma once
// Viewer camera motion: orbit about the look-at point (the CMSC 23700 viewer:
// arrows rotate, +/- zoom; seed 001 section 3.4) and first-person flight
// (WASD and mouse look; seed 004). Pure math on a Camera, no input code.
#include "renderer/scene/Camera.h"

namespace dw::camera {

// Rotates the eye about the target: yaw about world up, pitch towards the
// poles (stopping 1 degree short). Angles in radians.
void orbit(Camera& c, float yaw, float pitch);
// Moves the eye towards the target by `factor` (< 1 closer, > 1 farther).
void zoom(Camera& c, float factor);
// Shifts eye and target in the view plane by fractions of the eye distance.
void pan(Camera& c, float right, float up);
// Moves eye and target in the camera frame: x right, y world up, z forward.
void fly(Camera& c, const glm::vec3& move);
// Turns the view direction; the target stays at the same distance ahead.
void look(Camera& c, float yaw, float pitch);
float distance(const Camera& c);

}  // namespace dw::camera
