#pragma once
// Procedural meshes for built-in scenes and the scene JSON's "shape" objects.
// All have normals, texture coordinates and tangents.
#include "renderer/scene/Mesh.h"

namespace dw::shapes {

// Axis-aligned box centred on the origin; uvScale repeats textures per unit.
Mesh box(const glm::vec3& size, float uvScale = 1.0f);
// Plane in XZ facing +Y, centred on the origin.
Mesh plane(float sizeX, float sizeZ, float uvScale = 1.0f);
Mesh sphere(float radius, int slices = 32, int stacks = 16);
// Capped cylinder along +Y from y = 0 to y = height.
Mesh cylinder(float radius, float height, int segments = 24);
// Cone along +Y: base radius at y = 0, apex at y = height.
Mesh cone(float radius, float height, int segments = 24);

}  // namespace dw::shapes
