#pragma once
// The scene model every loader produces and the renderer draws: meshes,
// materials, images, instances, lights, camera and the global terms.
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "renderer/scene/Camera.h"
#include "renderer/scene/Image.h"
#include "renderer/scene/Light.h"
#include "renderer/scene/Material.h"
#include "renderer/scene/Mesh.h"

namespace dw {

struct MeshInstance {
    int mesh = 0;
    glm::mat4 transform{1.0f};
};

struct Scene {
    std::string name;
    std::string source;  // file path, or "builtin:<name>"
    Camera camera;
    glm::vec3 ambient{0.05f};
    glm::vec3 background{0.0f};  // HDR colour of pixels no geometry covers
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    std::vector<std::string> warnings;  // things loaded with a fallback
    // Knob values the scene is meant to be seen with ("tonemap.key" -> "0.05"),
    // applied when it loads, before presets and --set.
    std::vector<std::pair<std::string, std::string>> settings;

    Bounds bounds() const;
    int countLights(LightType type, bool enabledOnly = true) const;
    bool hasMaterial(AlphaMode mode) const;
    size_t triangleCount() const;
    // Appends a material/image and returns its index.
    int addMaterial(Material m);
    int addImage(Image img);
    int addMesh(Mesh m);
};

}  // namespace dw
