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

}  // namespace dw
