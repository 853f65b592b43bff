#include "renderer/reference/ReferenceJob.h"

#include <sstream>
#include <utility>

#include "renderer/reference/ReferenceCache.h"

namespace dw::reference {

std::string viewKey(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request) {
    std::ostringstream s;
    s.precision(9);
    const Camera& c = request.camera;
    s << scene.source << "|" << request.width << "x" << request.height << "|" << c.position.x << "," << c.position.y << ","
      << c.position.z << "|" << c.target.x << "," << c.target.y << "," << c.target.z << "|" << c.up.x << "," << c.up.y
      << "," << c.up.z << "|" << c.fovYDegrees << "," << c.nearPlane << "," << c.farPlane << "|" << model.canonical();
    if (!scene.animation.empty()) s << "|t=" << scene.animation.posedAt;  // the pose (the Scene panel's timeline)
    for (const Light& l : scene.lights)
        s << "|" << l.enabled << l.castShadows << l.position.x << "," << l.position.y << "," << l.position.z << ","
          << l.direction.x << "," << l.direction.y << "," << l.direction.z << "," << l.intensity.r << "," << l.intensity.g
          << "," << l.intensity.b << "," << l.cutoffDegrees << "," << l.exponent << "," << l.attenuation.constant << ","
          << l.attenuation.linear << "," << l.attenuation.quadratic;
    return s.str();
}

ReferenceJob::~ReferenceJob() {
    cancel();
    join();
}

void ReferenceJob::join() {
    if (worker_.joinable()) worker_.join();
}

void ReferenceJob::cancel() {
    if (progress_) progress_->cancel = true;
}

void ReferenceJob::start(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request) {
    cancel();
    join();
    key_ = viewKey(scene, model, request);
    progress_ = std::make_unique<ReferenceProgress>();
    running_ = true;
    auto copy = std::make_shared<Scene>(scene);
    ReferenceProgress* progress = progress_.get();
    const std::string key = key_;
    worker_ = std::thread([this, copy, model, request, progress, key] {
        std::shared_ptr<const ReferenceImages> images;
        std::string error;
        try {
            const ReferenceCache cache;
            const std::string cacheKey = referenceKey(*copy, model, request);
            if (auto hit = cache.load(cacheKey)) {
                images = std::make_shared<const ReferenceImages>(std::move(*hit));
            } else {
                auto fresh = std::make_shared<ReferenceImages>(renderReference(*copy, model, request, progress, &rayScenes_));
                try {
                    cache.store(cacheKey, *fresh);
                } catch (const std::exception&) {
                    // An unwritable cache costs the next run a render; the images stand.
                }
                images = std::move(fresh);
            }
        } catch (const ReferenceCancelled&) {
            error = "cancelled";
        } catch (const std::exception& e) {
            error = e.what();
        }
        {
            std::lock_guard<std::mutex> lock(mutex_);
            result_ = images;
            resultKey_ = key;
            error_ = error;
        }
        running_ = false;
    });
}

std::shared_ptr<const ReferenceImages> ReferenceJob::takeResult(std::string* key) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (key) *key = resultKey_;
    return std::exchange(result_, nullptr);
}

std::string ReferenceJob::takeError() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(error_, std::string());
}

}  // namespace dw::reference
