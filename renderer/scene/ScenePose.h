#pragma once
// Poses a scene at a scene time (issue 36): evaluates Scene::animation
// (Animation.h) at `seconds` and writes the result into the scene itself:
// the transforms of the mesh instances glTF nodes place, and the vertices
// (positions, normals, tangents) and bounds of the skinned and morphed
// meshes. Everything that reads the Scene (GpuScene, the CPU reference's ray
// scene, bounds and culling) then sees that pose. Costs O(animated nodes +
// deformed vertices x (joints per vertex + morph targets)) on the CPU; a
// no-op for a scene without animation or already posed at `seconds`.
// Returns whether anything was written.
namespace dw {

struct Scene;

bool poseScene(Scene& scene, double seconds);

}  // namespace dw
