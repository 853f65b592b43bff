#pragma once
// The CPU reference of one view, traced as `reference` traces it (issue 24):
// the scene (as frame N has it: flame particles move with the frame index),
// the knobs that define the model (ReferenceModel::fromKnobs), the camera,
// the size, and `reference`'s options (--ao-rays, --seed, --threads, the
// cache). One function used by `render --buffer reference.*|compare.error`
// (app/RenderCommand.cpp), replay and the Python module's Session.render and
// Session.reference (python/WorkbenchSession.cpp), so all trace the same
// image bit for bit. CPU only (Embree, oneTBB); no GL. The session is above
// this floor: it hands over its scene, knobs and camera, and shows the
// images through RenderSession::showReference.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "renderer/knobs/KnobRegistry.h"
#include "renderer/reference/RaySceneCache.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/scene/Camera.h"
#include "renderer/scene/Scene.h"

namespace dw::reference {

// `reference`'s options (ranges: renderer/OptionLimits.h, kAoRays, kSeed,
// kReferenceThreads; checked here, Error outside them).
struct ViewReferenceOptions {
    int aoRays = 64;   // --ao-rays: cosine-weighted AO rays per pixel
    int seed = 1;      // --seed: the AO sample pattern's and the pixel samples' seed
    int pixelSamples = 1;                   // --spp: samples per pixel (kPixelSamples)
    PixelFilter pixelFilter = PixelFilter::Box;  // --filter
    int threads = 0;   // --threads; 0: every core; more than the machine's cores: its cores (same image for any)
    bool useCache = true;        // false: --no-cache (trace, and store nothing)
    std::string cacheDirectory;  // --cache-dir; empty: ReferenceCache's default ($DW_REFERENCE_CACHE, ~/.cache/...)
    // Counts finished pixels; its `cancel` stops the trace (ReferenceCancelled is thrown).
    ReferenceProgress* progress = nullptr;
    // A cache that cannot be written: when set, called with the reason and the
    // images are still returned (as `reference` warns); when empty, Error is thrown.
    std::function<void(const std::string&)> cacheWarning;
    // Where the scene's ray scene is kept between references (RaySceneCache.h:
    // the caller's, e.g. a Python Session's, so its cameras share one build);
    // null: one built for this trace. The same image either way.
    RaySceneCache* rayScenes = nullptr;
};

struct ViewReference {
    ReferenceImages images;  // W x H, rows top-down (ReferenceRenderer.h's buffers)
    ReferenceModel model;    // what was traced (fromKnobs, with aoRays and seed)
    std::string key;         // the cache key
    bool cached = false;     // read from the cache, not traced
};

// The reference of a view at `width` x `height` pixels: `knobs` (those that
// define the model) and `camera` as they are, `scene` as frame `frame` has it
// (its flame particles moved there; none: as given). Reads its arguments
// without changing them (no GL call), so it runs on any thread while the
// caller's session waits. Throws Error (options out of range, Embree
// failures, a size below 1x1, an unwritable cache without cacheWarning) or
// ReferenceCancelled.
ViewReference traceViewReference(const Scene& scene, const KnobRegistry& knobs, const Camera& camera, int width,
                                 int height, const ViewReferenceOptions& options,
                                 std::optional<std::uint64_t> frame = std::nullopt);

}  // namespace dw::reference
