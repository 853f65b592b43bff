#include "renderer/reference/ViewReference.h"

#include <algorithm>
#include <exception>
#include <filesystem>

#include "renderer/OptionLimits.h"
#include "renderer/reference/ReferenceCache.h"
#include "renderer/scene/FlameParticles.h"

namespace dw::reference {

ViewReference traceViewReference(const Scene& given, const KnobRegistry& knobs, const Camera& camera, int width,
                                 int height, const ViewReferenceOptions& options, std::optional<std::uint64_t> frame) {
    if (!limits::kAoRays.holds(options.aoRays) || !limits::kSeed.holds(options.seed) ||
        !limits::kReferenceThreads.holds(options.threads) || !limits::kPixelSamples.holds(options.pixelSamples))
        throw Error("reference: ao_rays, seed, spp or threads outside reference's ranges (renderer/OptionLimits.h)");
    std::optional<Scene> animated;
    if (frame) {
        animated = given;
        animateFlameParticles(*animated, *frame);
    }
    const Scene& scene = animated ? *animated : given;
    ViewReference out;
    out.model = ReferenceModel::fromKnobs(knobs, scene);
    out.model.aoRays = options.aoRays;
    out.model.seed = static_cast<std::uint32_t>(options.seed);
    out.model.pixelSamples = options.pixelSamples;
    out.model.pixelFilter = options.pixelFilter;
    ReferenceRequest request;
    request.camera = camera;
    request.width = width;
    request.height = height;
    // oneTBB runs at most as many threads as the machine has cores (as reference --threads).
    request.threads = options.threads > 0 ? std::min(options.threads, availableThreads()) : 0;
    const ReferenceCache cache(options.cacheDirectory.empty() ? std::filesystem::path()
                                                              : std::filesystem::path(options.cacheDirectory));
    out.key = referenceKey(scene, out.model, request);
    if (options.useCache) {
        if (auto cached = cache.load(out.key)) {
            out.images = std::move(*cached);
            out.cached = true;
            return out;
        }
    }
    out.images = renderReference(scene, out.model, request, options.progress, options.rayScenes);
    if (options.useCache) {
        if (!options.cacheWarning) {
            cache.store(out.key, out.images);
        } else {
            try {
                cache.store(out.key, out.images);
            } catch (const std::exception& e) {
                options.cacheWarning(e.what());
            }
        }
    }
    return out;
}

}  // namespace dw::reference
