#pragma once
// The scene model every loader produces and the renderer draws: meshes,
// materials, images, instances, lights, camera and the global terms.
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "renderer/io/ImageIO.h"
#include "renderer/scene/Animation.h"
#include "renderer/scene/Camera.h"
#include "renderer/scene/FlameParticles.h"
#include "renderer/io/Image.h"
#include "renderer/scene/Light.h"
#include "renderer/scene/Material.h"
#include "renderer/scene/Mesh.h"

namespace dw {

// What covers the pixels no geometry covers (seed 004 "Skybox").
struct Sky {
    enum class Kind { Color, Procedural, Environment };
    Kind kind = Kind::Color;  // Color: Scene::background
    // Procedural: a gradient from the horizon to the zenith (and to the ground
    // below the horizon), with a sun disc towards the first directional light.
    glm::vec3 zenith{0.12f, 0.22f, 0.48f};
    glm::vec3 horizon{0.62f, 0.66f, 0.72f};
    glm::vec3 ground{0.12f, 0.11f, 0.10f};
    float sunSizeDegrees = 1.5f;
    // Environment: an equirectangular (lat-long) image, or a cube map from six
    // images in GL face order +X -X +Y -Y +Z -Z. HDR/EXR or any OIIO format.
    std::string environmentSource;
    FloatImage equirect;
    std::vector<FloatImage> cubeFaces;
    float intensity = 1.0f;
    float rotationDegrees = 0.0f;  // about +Y
};

struct MeshInstance {
    int mesh = 0;
    glm::mat4 transform{1.0f};
};

struct Scene {
    std::string name;
    std::string source;  // file path, or "builtin:<name>"
    Camera camera;
    // A keyframed walk-through (scene JSON camera.path) for bench --walkthrough; usually empty.
    std::vector<CameraKeyframe> cameraPath;
    glm::vec3 ambient{0.05f};
    glm::vec3 background{0.0f};  // HDR colour of pixels no geometry covers (Sky::Kind::Color)
    Sky sky;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    // Flame particles that are point lights (the built-in "fire" scene): which
    // of `lights` they are and how they move; animateFlameParticles() sets them
    // for a frame index (RenderSession::render and the GUI do, every frame).
    FlameParticles flames;
    // glTF nodes, skins, morph targets and animation clips (Animation.h);
    // poseScene (ScenePose.h) writes their pose at a scene time into
    // `instances` and `meshes`. Empty for a scene without them.
    SceneAnimation animation;
    std::vector<std::string> warnings;  // things loaded with a fallback
    // Knob values the scene is meant to be seen with ("tonemap.key" -> "0.05"),
    // applied when it loads, before presets and --set.
    std::vector<std::pair<std::string, std::string>> settings;
    // The external files each glTF file the loader read names: its buffers'
    // and then its images' URIs (data: URIs left out), as its JSON gives them,
    // by the file's path (lexically normal). Taken from the loader's one parse
    // of the JSON, so the experiment record lists a scene's files
    // (record/SceneFiles) without parsing the file again.
    std::map<std::string, std::vector<std::string>> gltfExternalUris;

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
