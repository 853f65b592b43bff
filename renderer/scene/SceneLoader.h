#pragma once
// Opens what --scene names: a built-in scene, a scene JSON, or a glTF file.
// A glTF file without lights gets a documented default rig (a key light, a
// fill light and ambient), and without a camera one framing its bounds.
#include <string>

#include "renderer/scene/Scene.h"

namespace dw {

Scene loadScene(const std::string& spec);
// Adds the default rig used for glTF files that bring no lights of their own.
void addDefaultLightRig(Scene& scene);

}  // namespace dw
