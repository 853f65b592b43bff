#include "app/TradeoffMeasurement.h"

#include <cstdio>
#include <map>
#include <optional>

#include "app/HeadlessGlContext.h"
#include "app/HostInfo.h"
#include "renderer/Error.h"
#include "renderer/reference/ReferenceCache.h"
#include "renderer/reference/ReferenceRenderer.h"

namespace dw {

TradeoffMeasurement measureTradeoff(TradeoffRunner& runner, int aoRays, bool quiet) {
    auto say = [&](const std::string& line) {
        if (!quiet) std::fprintf(stderr, "%s\n", line.c_str());
    };
    // References through the shared cache; each distinct one rendered once in this run.
    const reference::ReferenceCache cache;
    std::map<std::string, reference::ReferenceImages> rendered;
    bool noted = false;
    int references = 0, cachedReferences = 0;
    double referenceSeconds = 0.0;
    const TradeoffReference reference = [&](const Scene& scene, const KnobRegistry& k, const Camera& camera, int width,
                                            int height, const std::string& buffer) {
        reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(k, scene);
        model.aoRays = aoRays;
        reference::ReferenceRequest request;
        request.camera = camera;
        request.width = width;
        request.height = height;
        const std::string key = reference::referenceKey(scene, model, request);
        auto it = rendered.find(key);
        if (it == rendered.end()) {
            std::optional<reference::ReferenceImages> images = cache.load(key);
            if (images) {
                ++cachedReferences;
            } else {
                say("tradeoff: rendering the CPU reference (" + std::to_string(width) + "x" + std::to_string(height) +
                    (model.rayTracedAo ? ", " + std::to_string(model.aoRays) + " AO rays" : std::string()) +
                    "; cached for the next run)");
                images = reference::renderReference(scene, model, request);
                ++references;
                referenceSeconds += images->stats.seconds + images->stats.buildSeconds;
                try {
                    cache.store(key, *images);
                } catch (const std::exception& e) {
                    std::fprintf(stderr, "warning: the reference is not cached: %s\n", e.what());
                }
            }
            if (!noted && buffer == "final") {
                const reference::KnobReport report = reference::reportKnobs(k, model);
                if (!report.unmodelledOn.empty()) {
                    std::string on;
                    for (const auto& n : report.unmodelledOn) on += " " + n;
                    std::fprintf(stderr, "note: the reference's final image has no%s (set them false to measure the "
                                         "shading alone)\n", on.c_str());
                }
                noted = true;
            }
            it = rendered.emplace(key, std::move(*images)).first;
        }
        const FloatImage* image = it->second.buffer(buffer);
        if (!image) throw Error("the reference has no buffer '" + buffer + "'");
        return *image;
    };

    auto context = HeadlessGlContext::create();
    TradeoffMeasurement m;
    m.result = runner.run(reference, say);
    TradeoffResult& result = m.result;
    BenchFields& machine = m.machine;
    machine = result.machine;
    machine.emplace_back("gl_platform", context->platform());
    machine.emplace_back("cpu", cpuModel());
    machine.emplace_back("compiler", compilerName());
    machine.emplace_back("date", utcNow());
    if (runner.options().against.empty()) {
        result.settings.emplace_back("references_rendered", std::to_string(references));
        result.settings.emplace_back("references_from_cache", std::to_string(cachedReferences));
        char text[32];
        std::snprintf(text, sizeof(text), "%.6g", referenceSeconds);
        result.settings.emplace_back("reference_seconds", text);
    }
    return m;
}

}  // namespace dw
