#pragma once
// The KHR_lights_punctual lights and the first perspective camera of a glTF
// file (the extension's spec; glTF 2.0 spec 3.10 "Cameras"), placed by the
// world transform of the node that holds them: a light or camera looks down
// its node's -Z, a camera's up is its node's +Y. A node transform with no
// extent along those axes (zero scale) or beyond a float is an error naming
// the light or camera.
#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "renderer/scene/GltfLoader.h"
#include "renderer/scene/Scene.h"

namespace dw {

class GltfLightImporter {
public:
    // `model`, `path` (the file) and `scene` outlive the importer.
    GltfLightImporter(const tinygltf::Model& model, const std::string& path, Scene& scene)
        : model_(model), path_(path), scene_(scene) {}

    // Adds the node's KHR_lights_punctual light, if it has one.
    void importNodeLight(const tinygltf::Node& node, const glm::mat4& world, GltfImport& result);
    // Sets the scene's camera from a perspective camera (orthographic ones are not used).
    void importCamera(const tinygltf::Camera& cam, const glm::mat4& world, GltfImport& result);

private:
    static std::optional<glm::vec3> unitAxis(const glm::mat4& world, const glm::vec4& axis);
    [[noreturn]] void fail(const std::string& what) const;

    const tinygltf::Model& model_;
    const std::string& path_;
    Scene& scene_;
};

}  // namespace dw
