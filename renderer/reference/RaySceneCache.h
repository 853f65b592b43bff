#pragma once
// Where the reference's ray scene lives (issue 33, "a scene read once"): the
// Embree scene of the scene being referenced, built once relative to the
// scene's centre (RayScene::sceneCentre) and reused by every camera and sweep
// point that traces the same content, instead of one build per reference.
//
// Owned by whoever traces several references of one scene: a tradeoff run
// (TradeoffStudy::measure), the Python module's Session, the workbench's
// ReferenceJob, `render` of reference buffers. It holds one ray scene, the
// last one asked for: a scene of other content (sceneGeometryKey: another
// file, flame particles moved by a frame) replaces it. A RayScene keeps
// copies of what its queries read, so it outlives the Scene it came from.
// Thread-safe; the RayScene handed out is immutable and may be queried from
// any number of threads.
#include <memory>
#include <mutex>
#include <string>

#include "renderer/reference/RayScene.h"

namespace dw::reference {

class RaySceneCache {
public:
    // The RayScene of `scene`: the one held when its content is `scene`'s,
    // else a new build (which the cache then holds). `seconds`, when given,
    // receives the time spent here (the content's hash and any build).
    // Throws Error (Embree failures).
    std::shared_ptr<const RayScene> get(const Scene& scene, double* seconds = nullptr);
    // Lets go of the held ray scene (its memory is freed once no render uses it).
    void clear();

private:
    std::mutex mutex_;
    std::string key_;
    std::shared_ptr<const RayScene> held_;
};

}  // namespace dw::reference
