#pragma once
// The CPU references a study measures against, through the shared cache
// (reference::ReferenceCache): each distinct one (scene content, the model
// the knobs make, camera, size, AO rays, seed, samples per pixel and filter) rendered at most once per
// run, loaded from the cache when it is there and stored after; the ones
// rendered trace one ray scene (reference::RaySceneCache) across cameras. `tradeoff`
// (TradeoffStudy::measure) and `tradeoff --attribute` (ErrorAttribution)
// hand it to their runners as their TradeoffReference.
// Needs no GL (the reference is traced on the CPU).
#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "renderer/bench/TradeoffRunner.h"
#include "renderer/reference/RaySceneCache.h"
#include "renderer/reference/ReferenceCache.h"
#include "renderer/reference/ReferenceRenderer.h"

namespace dw {

// The references' pixel samples (tradeoff --ref-spp N, --ref-filter box|tent;
// reference --spp, --filter): N points over the filter's footprint per pixel,
// textures read at their base level at each (ReferenceModel::pixelSamples);
// 1 (the default) traces the pixel's centre. Part of the cache key (the
// model's canonical text), so two N never share an entry.
struct ReferencePixels {
    int samples = 1;  // 1 .. 65536 (renderer/OptionLimits.h kPixelSamples)
    reference::PixelFilter filter = reference::PixelFilter::Box;
};

class CachedReferences {
public:
    struct Hooks {
        std::function<void(const std::string&)> line;     // "tradeoff: rendering the CPU reference ..."
        std::function<void(const std::string&)> warning;  // a cache that cannot be written; effects not modelled
        std::function<void()> stopIfAsked;                // throws to stop before a reference is traced
    };
    // `aoRays` AO rays per pixel, their pattern (and the pixel samples') seeded
    // by `seed` (reference --seed); `pixels` samples per pixel.
    CachedReferences(int aoRays, std::uint32_t seed, Hooks hooks, ReferencePixels pixels = {})
        : aoRays_(aoRays), seed_(seed), pixels_(pixels), hooks_(std::move(hooks)) {}

    // The reference's `buffer` (final, lbuffer, ao, shadow) of the view.
    // Throws Error when the reference has no such buffer.
    FloatImage image(const Scene& scene, const KnobRegistry& knobs, const Camera& camera, int width, int height,
                     const std::string& buffer);
    // As a TradeoffReference (this object must outlive it).
    TradeoffReference function() {
        return [this](const Scene& s, const KnobRegistry& k, const Camera& c, int w, int h, const std::string& b) {
            return image(s, k, c, w, h, b);
        };
    }

    int rendered() const { return rendered_; }
    int fromCache() const { return fromCache_; }
    double seconds() const { return seconds_; }  // tracing and building the rendered ones

private:
    void noteUnmodelled(const KnobRegistry& knobs, const reference::ReferenceModel& model);
    int aoRays_;
    std::uint32_t seed_;
    ReferencePixels pixels_;
    Hooks hooks_;
    const reference::ReferenceCache cache_;
    // One ray scene for every camera and sweep point of the run (rebuilt only
    // when the scene's content changes, as flame particles do by frame).
    reference::RaySceneCache rayScenes_;
    std::map<std::string, reference::ReferenceImages> images_;
    bool noted_ = false;
    int rendered_ = 0, fromCache_ = 0;
    double seconds_ = 0.0;
};

}  // namespace dw
