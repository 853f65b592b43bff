#include "renderer/study/CachedReferences.h"

#include <optional>

#include "renderer/Error.h"

namespace dw {

FloatImage CachedReferences::image(const Scene& scene, const KnobRegistry& knobs, const Camera& camera, int width,
                                   int height, const std::string& buffer) {
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(knobs, scene);
    model.aoRays = aoRays_;
    model.seed = seed_;
    model.pixelSamples = pixels_.samples;
    model.pixelFilter = pixels_.filter;
    reference::ReferenceRequest request;
    request.camera = camera;
    request.width = width;
    request.height = height;
    const std::string key = reference::referenceKey(scene, model, request);
    auto it = images_.find(key);
    if (it == images_.end()) {
        if (hooks_.stopIfAsked) hooks_.stopIfAsked();
        std::optional<reference::ReferenceImages> images = cache_.load(key);
        if (images) {
            ++fromCache_;
        } else {
            if (hooks_.stopIfAsked) hooks_.stopIfAsked();
            if (hooks_.line)
                hooks_.line("tradeoff: rendering the CPU reference (" + std::to_string(width) + "x" + std::to_string(height) +
                            (model.rayTracedAo ? ", " + std::to_string(model.aoRays) + " AO rays" : std::string()) +
                            (model.pixelSamples > 1 ? ", " + std::to_string(model.pixelSamples) + " samples per pixel (" +
                                                          reference::pixelFilterName(model.pixelFilter) + ")"
                                                    : std::string()) +
                            "; cached for the next run)");
            images = reference::renderReference(scene, model, request, nullptr, &rayScenes_);
            ++rendered_;
            seconds_ += images->stats.seconds + images->stats.buildSeconds;
            try {
                cache_.store(key, *images);
            } catch (const std::exception& e) {
                if (hooks_.warning) hooks_.warning(std::string("warning: the reference is not cached: ") + e.what());
            }
        }
        if (buffer == "final") noteUnmodelled(knobs, model);
        it = images_.emplace(key, std::move(*images)).first;
    }
    const FloatImage* image = it->second.buffer(buffer);
    if (!image) throw Error("the reference has no buffer '" + buffer + "'");
    return *image;
}

// Once a run: the effects on that the reference's final image has not.
void CachedReferences::noteUnmodelled(const KnobRegistry& knobs, const reference::ReferenceModel& model) {
    if (noted_) return;
    noted_ = true;
    if (!hooks_.warning) return;
    if (model.pixelSamples <= 1)
        hooks_.warning("note: the reference is traced through the pixel centres (--ref-spp 1): anti-aliasing and "
                       "texture filtering are measured against the centres, not the pixel's area (--ref-spp 16 is "
                       "the footprint truth; docs/antialiasing.md)");
    const reference::KnobReport report = reference::reportKnobs(knobs, model);
    if (report.unmodelledOn.empty()) return;
    std::string on;
    for (const auto& n : report.unmodelledOn) on += (on.empty() ? " " : ", ") + n;
    hooks_.warning("note: the reference's final image has no " + on.substr(1) +
                   (report.unmodelledOn.size() > 1 ? " (set them false" : " (set it false") +
                   " to measure the shading alone)");
}

}  // namespace dw
