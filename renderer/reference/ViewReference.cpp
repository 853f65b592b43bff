#include "renderer/reference/ViewReference.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <memory>

#include "renderer/OptionLimits.h"
#include "renderer/passes/ReferencePass.h"
#include "renderer/reference/ReferenceCache.h"
#include "renderer/scene/FlameParticles.h"

namespace dw::reference {

ViewReference traceViewReference(RenderSession& session, int width, int height, const ViewReferenceOptions& options,
                                 std::optional<std::uint64_t> frame) {
    if (!limits::kAoRays.holds(options.aoRays) || !limits::kSeed.holds(options.seed) ||
        !limits::kReferenceThreads.holds(options.threads))
        throw Error("reference: ao_rays, seed or threads outside reference's ranges (renderer/OptionLimits.h)");
    std::optional<Scene> animated;
    if (frame) {
        animated = session.scene();
        animateFlameParticles(*animated, *frame);
    }
    const Scene& scene = animated ? *animated : session.scene();
    ViewReference out;
    out.model = ReferenceModel::fromKnobs(session.knobs(), scene);
    out.model.aoRays = options.aoRays;
    out.model.seed = static_cast<std::uint32_t>(options.seed);
    ReferenceRequest request;
    request.camera = session.camera();
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
    out.images = renderReference(scene, out.model, request, options.progress);
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

void showViewReference(RenderSession& session, const ReferenceImages* images, const std::string& staleReason) {
    auto* pass = session.pipeline().pass<ReferencePass>();
    if (!pass) return;
    if (images) {
        auto shown = std::make_shared<ReferencePass::Images>();
        shown->lbuffer = images->lbuffer;
        shown->final = images->final;
        shown->ao = images->ao;
        shown->describe = "CPU reference (" + std::to_string(images->stats.primaryRays) + " primary rays)";
        pass->setReference(std::move(shown));
    } else if (pass->hasReference()) {
        pass->setReference(nullptr, staleReason);
    }
}

bool isReferenceOutput(RenderSession& session, const std::string& buffer) {
    const PublishedOutput* o = session.pipeline().outputs().find(buffer);
    return o && o->pass == "reference";
}

}  // namespace dw::reference
