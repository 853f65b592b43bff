#pragma once
// The project's scene JSON (docs/scene-format.md): camera, ambient, lights with
// the CMSC 23700 fields (seed 001, section 3.1), materials, and objects that
// are glTF files or built-in shapes with transforms.
#include <string>

#include "renderer/scene/Scene.h"

namespace dw {

// Throws FileError naming the file and the JSON path of the problem, e.g.
// "s.json: lights[2].attenuation.quadratic: expected a number, got string".
Scene loadSceneJson(const std::string& path);
// Same, from text (`path` is used for messages and relative file names).
Scene parseSceneJson(const std::string& text, const std::string& path);

}  // namespace dw
