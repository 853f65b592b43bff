#pragma once
// The content hash of a scene as loaded, for the records of built-in scenes
// (renderer/scene/BuiltinScenes), which read no file whose sha256 could be
// recorded: a built-in changed by a new build replayed as "inputs changed:
// none". The hash is the sha256 of a fixed serialisation of what the scene
// model holds: every mesh (name, vertices, indices, material), material,
// image (size and pixels), instance, light, the camera and its path, the
// ambient, background and sky terms, the fire's emitters and the scene's
// knob settings. The fire's particle lights are left out (they move with the
// frame index; their emitters, which make them, are in), so the hash of a
// scene is the same before and after any frame. Needs no GL.
#include <string>

#include "renderer/scene/Scene.h"

namespace dw {

// Hex sha256 of `scene`'s content (above). The same for the same content on
// any machine (little-endian float and integer bytes, lengths before lists).
std::string sceneContentSha256(const Scene& scene);

}  // namespace dw
