#include "renderer/scene/SceneLoader.h"
#include "renderer/scene/SceneFileKind.h"

#include <algorithm>
#include <filesystem>

#include "renderer/Error.h"
#include "renderer/scene/BuiltinScenes.h"
#include "renderer/scene/GltfLoader.h"
#include "renderer/scene/SceneCheck.h"
#include "renderer/scene/SceneJsonLoader.h"

namespace dw {

namespace fs = std::filesystem;

void addDefaultLightRig(Scene& scene) {
    const Bounds b = scene.bounds();
    const float r = std::max(b.radius(), 1e-3f);
    Light key;
    key.name = "default key";
    key.type = LightType::Directional;
    key.direction = glm::normalize(glm::vec3(-0.4f, -0.8f, -0.45f));
    key.intensity = glm::vec3(1.0f, 0.97f, 0.92f) * 1.2f;
    key.castShadows = true;
    scene.lights.push_back(key);
    Light fill;
    fill.name = "default fill";
    fill.type = LightType::Point;
    fill.position = (b.empty() ? glm::vec3(0.0f) : b.center()) + glm::vec3(r * 1.2f, r * 0.6f, r * 1.0f);
    fill.intensity = glm::vec3(0.55f, 0.6f, 0.7f);
    // 1/(1 + (d/r)^2) falloff in scene units, so the rig scales with the model.
    fill.attenuation = {1.0f, 0.0f, 1.0f / (r * r)};
    scene.lights.push_back(fill);
    scene.ambient = glm::vec3(0.12f);
    scene.background = glm::vec3(0.05f, 0.055f, 0.065f);
    scene.sky.kind = Sky::Kind::Procedural;
}

Scene loadScene(const std::string& spec) {
    if (isBuiltinScene(spec)) return makeBuiltinScene(spec);
    // Scene::source of a built-in scene reads "builtin:<name>".
    if (spec.rfind("builtin:", 0) == 0 && isBuiltinScene(spec.substr(8))) return makeBuiltinScene(spec.substr(8));
    std::string ext = fs::path(spec).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext == ".json") {
        refuseNonSceneFile(spec);  // a record or a preset would load as an empty scene
        return loadSceneJson(spec);
    }
    if (ext == ".gltf" || ext == ".glb") {
        Scene scene;
        scene.source = spec;
        scene.name = fs::path(spec).stem().string();
        const GltfImport imported = importGltf(spec, scene, glm::mat4(1.0f), true);
        if (scene.instances.empty()) {
            // Say what was there instead (the warnings name skipped points, lines, empty primitives).
            std::string why = "the glTF scene contains no triangle meshes";
            int skipped = 0;
            for (const auto& w : scene.warnings) skipped += w.size() >= 9 && w.compare(w.size() - 9, 9, "; skipped") == 0;
            if (skipped > 0) why += " (" + std::to_string(skipped) + " primitive(s) of points, lines or no triangles skipped)";
            throw FileError(spec, why);
        }
        if (!imported.hasCamera) scene.camera = Camera::framing(imported.bounds);
        if (imported.lightCount == 0) addDefaultLightRig(scene);
        checkSceneValues(scene);  // what the nodes combine into (extent, transforms, framed camera)
        warnClampedEmission(scene);
        return scene;
    }
    if (!fs::exists(spec)) {
        std::string names;
        for (const auto& b : builtinScenes()) names += (names.empty() ? "" : ", ") + b.name;
        throw Error("--scene '" + spec + "' is neither a built-in scene (" + names + ") nor an existing file");
    }
    throw FileError(spec, "unknown scene format '" + ext + "' (expected .json, .gltf or .glb)");
}

}  // namespace dw
