#include "renderer/reference/RaySceneCache.h"

#include <chrono>

#include "renderer/reference/ReferenceCache.h"

namespace dw::reference {

std::shared_ptr<const RayScene> RaySceneCache::get(const Scene& scene, double* seconds) {
    const auto start = std::chrono::steady_clock::now();
    const std::string key = sceneGeometryKey(scene);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!held_ || key != key_) {
        held_.reset();  // the old one's memory first
        held_ = std::make_shared<const RayScene>(scene, RayScene::sceneCentre(scene));
        key_ = key;
    }
    if (seconds) *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return held_;
}

void RaySceneCache::clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    held_.reset();
    key_.clear();
}

}  // namespace dw::reference
