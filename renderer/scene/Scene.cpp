#include "renderer/scene/Scene.h"

namespace dw {

Bounds Scene::bounds() const {
    Bounds b;
    for (const auto& inst : instances) b.add(meshes[inst.mesh].bounds.transformed(inst.transform));
    return b;
}

int Scene::countLights(LightType type, bool enabledOnly) const {
    int n = 0;
    for (const auto& l : lights)
        if (l.type == type && (l.enabled || !enabledOnly)) ++n;
    return n;
}

bool Scene::hasMaterial(AlphaMode mode) const {
    for (const auto& inst : instances)
        if (materials[meshes[inst.mesh].material].alphaMode == mode) return true;
    return false;
}

size_t Scene::triangleCount() const {
    size_t n = 0;
    for (const auto& inst : instances) n += meshes[inst.mesh].indices.size() / 3;
    return n;
}

int Scene::addMaterial(Material m) {
    materials.push_back(std::move(m));
    return static_cast<int>(materials.size() - 1);
}

int Scene::addImage(Image img) {
    images.push_back(std::move(img));
    return static_cast<int>(images.size() - 1);
}

int Scene::addMesh(Mesh m) {
    if (m.bounds.empty()) m.computeBounds();
    meshes.push_back(std::move(m));
    return static_cast<int>(meshes.size() - 1);
}

}  // namespace dw
