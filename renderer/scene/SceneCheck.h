#pragma once
// The last check of a loaded scene, after every field was read and checked on
// its own: what fields combine into must still be finite 32-bit floats. A box
// 3e38 wide is a valid number but no valid extent (its diagonal overflows), a
// translation times a parent's scale can overflow, a camera framed around an
// enormous scene gets an infinite far plane. Each would otherwise reach the
// GPU as Inf/NaN and draw a black frame with exit code 0.
#include "renderer/scene/Scene.h"

namespace dw {

// Throws FileError(scene.source, "<what>: <problem>"): the scene's extent,
// every vertex (position, normal, texture coordinate, tangent), every instance transform, every light's position, direction and intensity,
// and the camera (CameraCheck.h, relative to the scene's extent).
void checkSceneValues(const Scene& scene);

// The largest emission any surface carries (R11F_G11F_B10F's largest value,
// less a margin): the G-buffer's emissive target cannot hold more, so
// shaders/geometry.frag, shaders/oit/transparent.frag (blended surfaces,
// every oit.method) and the CPU reference (MaterialEvaluator) all clamp
// emission to it: one rule for opaque and blended surfaces alike.
inline constexpr float kMaxEmission = 65000.0f;

// Adds to scene.warnings one line per material whose emissive factor
// (glTF: times KHR_materials_emissive_strength) is beyond kMaxEmission,
// naming the scene file, the material and the value: it is clamped, not refused.
void warnClampedEmission(Scene& scene);

}  // namespace dw
