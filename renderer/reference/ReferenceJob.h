#pragma once
// A reference render in the background (the workbench's "CPU reference of
// this view"): a copy of the scene, a worker thread, progress and cancel, and
// the reference cache, so the window never waits for it. One job at a time;
// starting another cancels the one running. The job keeps the scene's ray
// scene (RaySceneCache) for the next view of the same scene.
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "renderer/reference/RaySceneCache.h"
#include "renderer/reference/ReferenceRenderer.h"

namespace dw::reference {

// What a reference was rendered for, cheap to compare every frame: the scene's
// source and lights, the camera, the size and the model. When it changes the
// reference no longer shows the view.
std::string viewKey(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request);

class ReferenceJob {
public:
    ReferenceJob() = default;
    ~ReferenceJob();
    ReferenceJob(const ReferenceJob&) = delete;
    ReferenceJob& operator=(const ReferenceJob&) = delete;

    // Copies `scene`; looks the reference up in the cache, else renders and stores it.
    void start(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request);
    void cancel();
    bool running() const { return running_.load(); }
    double progress() const { return progress_ ? progress_->fraction() : 0.0; }
    // The finished images (once), else nothing. `key` is the viewKey they were rendered for.
    std::shared_ptr<const ReferenceImages> takeResult(std::string* key = nullptr);
    // The last job's failure ("" when none; "cancelled" after cancel()).
    std::string takeError();
    const std::string& runningKey() const { return key_; }

private:
    void join();
    std::thread worker_;
    std::unique_ptr<ReferenceProgress> progress_;
    std::atomic<bool> running_{false};
    std::mutex mutex_;
    std::shared_ptr<const ReferenceImages> result_;
    std::string resultKey_, error_, key_;
    RaySceneCache rayScenes_;  // the views of one scene share its ray scene
};

}  // namespace dw::reference
