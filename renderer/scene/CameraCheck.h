#pragma once
// The one definition of a usable camera, applied by every reader of cameras
// (scene JSON, presets, glTF): a camera it accepts gives a finite view and
// projection matrix. Fields are the scene JSON's names.
//  - fov in (0, 179) degrees, and at least 0.001;
//  - near a normal 32-bit float > 0 (not 0, not denormal), far > near;
//  - look-at differs from pos by more than kMinViewDistance times the larger
//    of the scene's extent and the camera's own coordinates (size-relative:
//    a scene 1e-8 across can be viewed from 1e-8 away);
//  - up not zero and not parallel to the view direction (look-at - pos);
//  - and, as the last word, view() and projection() are finite.
#include <optional>
#include <string>

#include "renderer/scene/Camera.h"

namespace dw {

// Relative distance below which pos and look-at count as the same point.
constexpr float kMinViewDistance = 1e-6f;
// sin of the smallest angle between up and the view direction.
constexpr float kMinUpAngleSin = 1e-4f;

struct CameraProblem {
    std::string field;  // "fov", "near", "far", "pos", "look-at", "up"
    std::string what;   // "must be greater than near (0.5), got 0.1"
};

// `sceneExtent`: the diagonal of the scene's bounds (0 when unknown).
std::optional<CameraProblem> findCameraProblem(const Camera& camera, float sceneExtent);

// Whether `up` is usable with the view direction of `camera` (not zero, not parallel).
bool upIsUsable(const Camera& camera);

}  // namespace dw
