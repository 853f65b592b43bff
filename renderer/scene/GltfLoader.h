#pragma once
// glTF 2.0 import through tinygltf, images decoded by OpenImageIO (tinygltf's
// image-loader hook). tinygltf accepts many invalid files (indices and
// accessors out of range, node cycles, non-finite positions) and throws
// std::bad_alloc on some: this loader checks what tinygltf does not and turns
// both into one FileError naming the file and the problem. Its parts, each
// with the spec section it follows: GltfCheck and GltfSchema (the container
// and JSON before tinygltf), GltfModelCheck (the model after it),
// GltfAccessors, GltfMaterials, GltfLights (docs/architecture.md, "glTF import").
#include <glm/glm.hpp>
#include <string>

#include "renderer/scene/Scene.h"

namespace dw {

struct GltfImport {
    bool hasCamera = false;   // the file had a camera node (scene.camera was set)
    int lightCount = 0;       // KHR_lights_punctual lights added
    Bounds bounds;            // world-space bounds of what was added
};

// Appends the default scene of `path` to `scene`, under `rootTransform`.
// Lights and the first camera are imported when `importLightsAndCamera`.
GltfImport importGltf(const std::string& path, Scene& scene, const glm::mat4& rootTransform,
                      bool importLightsAndCamera);

}  // namespace dw
