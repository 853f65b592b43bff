#pragma once
// Scenes the product carries in code, needing no files: "default" (a courtyard
// at dusk with columns, a sun and dozens of coloured point and spot lights),
// "street" (a night road lit by a long row of spot-light street lamps, the
// CMSC 23700 assignment's motivating case), "spheres" (a material grid) and
// "fire" (seed 004: flame particles that are point lights, hundreds of them,
// moved every frame by animateFlameParticles) and "atrium" (seed 000 section
// 6.5's large scene for the Overall preset: several hundred objects, hundreds
// of thousands of triangles, transparent objects, a shadowed sun).
#include <string>
#include <vector>

#include "renderer/scene/Scene.h"

namespace dw {

struct BuiltinSceneInfo {
    std::string name;
    std::string description;
};

const std::vector<BuiltinSceneInfo>& builtinScenes();
bool isBuiltinScene(const std::string& name);
// Throws dw::Error for an unknown name.
Scene makeBuiltinScene(const std::string& name);

}  // namespace dw
