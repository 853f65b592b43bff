// deferred-workbench reference: the CPU ground truth of one view, headless,
// with no GL at all (renderer/reference/ReferenceRenderer.h).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <fstream>
#include <tuple>

#include "app/Commands.h"
#include "app/ReferenceProgressLine.h"
#include "headless/CommandLine.h"
#include "renderer/Error.h"
#include "renderer/reference/ReferenceCache.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

// Renders on a worker thread while this one reports progress on stderr
// (app/ReferenceProgressLine.h); Ctrl+C (SIGINT) or SIGTERM cancels.
reference::ReferenceImages renderWithProgress(const Scene& scene, const reference::ReferenceModel& model,
                                              const reference::ReferenceRequest& request, bool quiet) {
    reference::ReferenceImages result;
    traceWithProgressLine(
        [&](reference::ReferenceProgress* progress) {
            result = reference::renderReference(scene, model, request, progress);
        },
        request.width, request.height, quiet);
    return result;
}

}  // namespace

int runReferenceCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2, "reference");
    if (cl.flag("--help")) {
        std::cout
            << "usage: deferred-workbench reference [--scene NAME|FILE] [--size WxH] [--buffer lbuffer|final|ao|shadow|spp_error]\n"
               "                                    [--preset NAME|FILE] [--set knob=value]... [--ao-rays N] [--seed N]\n"
               "                                    [--spp N] [--filter box|tent]\n"
               "                                    [--threads N] [--no-cache] [--cache-dir DIR] [--stats-out FILE]\n"
               "                                    [--throughput] [--quiet] --out FILE\n"
               "The CPU ground truth of the view: the GPU's shading model without its approximations, in double\n"
               "precision on exact geometry traced with Embree (docs/reference.md). No GL is used.\n"
               "  --buffer     lbuffer (HDR radiance, the default), final (tone-mapped), ao (ray-traced ambient\n"
               "               accessibility), shadow (share of the shadow-casting lights' light that arrives),\n"
               "               spp_error (the standard error of each pixel's luminance over its samples)\n"
               "  --out        .exr writes the raw values; .png the values in [0, 1] (not for lbuffer)\n"
               "  --preset, --set  as for render: the knobs that define the model are honoured (shadows.enabled,\n"
               "               shadows.blended_casters, ao.enabled, the radius of the method ao.method names:\n"
               "               ssao.radius/radius_unit/intensity, gtao.radius/radius_unit or aov.radius/radius_unit),\n"
               "               lighting.attenuation and its window,\n"
               "               lighting.ambient_*, skybox.*, tonemap.*, luminance.*); the rest choose GPU\n"
               "               approximations and are ignored, and the run says which of those were set\n"
               "  --ao-rays    cosine-weighted AO rays per pixel (default 64); the standard error is reported\n"
               "  --seed       the AO rays' and the pixel samples' seed (default 1); the image is the same for any --threads\n"
               "  --spp        samples per pixel (default 1: the pixel's centre, as the rasteriser samples): N points\n"
               "               over the pixel's footprint, each tracing everything, averaged: the truth of the\n"
               "               pixel's area (textures at their base level at each point); the run says whether N\n"
               "               is enough (the estimate's standard error under half an 8-bit step of the final image)\n"
               "  --filter     the footprint's weighting: box (the pixel's square, the default) or tent (radius 1 px)\n"
               "  --threads    worker threads (default: all cores)\n"
               "  --no-cache   render even when the cache holds this reference, and do not store it\n"
               "  --cache-dir  the cache (default $DW_REFERENCE_CACHE, else ~/.cache/deferred-workbench/reference)\n"
               "  --stats-out  write the render's statistics as JSON\n"
               "  --throughput also trace the same rays with Embree alone and print the ratio of rays per second\n"
               "Progress goes to stderr; Ctrl+C cancels (exit 130, nothing cached).\n"
                  << CommandLine::rangesHelp("reference");
        return 0;
    }
    RunConfig run = cl.runConfig();
    std::tie(run.width, run.height) = cl.size().value_or(std::pair{1280, 720});
    const std::string buffer = cl.value("--buffer").value_or("lbuffer");
    const auto out = cl.value("--out");
    const int aoRays = cl.whole("--ao-rays", 64);
    const int seed = cl.whole("--seed", 1);
    const int spp = cl.whole("--spp", 1);
    const std::string filter = cl.value("--filter").value_or("box");
    const int requestedThreads = cl.whole("--threads", 0);
    // oneTBB runs at most as many threads as the machine has cores; more are not asked for.
    const int threads = requestedThreads > 0 ? std::min(requestedThreads, reference::availableThreads()) : 0;
    if (requestedThreads > threads && threads > 0)
        std::fprintf(stderr, "note: --threads %d: this machine runs %d at once; using %d\n", requestedThreads, threads, threads);
    const bool noCache = cl.flag("--no-cache");
    const auto cacheDir = cl.value("--cache-dir");
    const auto statsOut = cl.value("--stats-out");
    const bool throughput = cl.flag("--throughput");
    const bool quiet = cl.flag("--quiet");
    cl.finish("reference");
    if (!cl.positional().empty()) throw UsageError("reference: unexpected argument '" + cl.positional()[0] + "'");
    if (!out) throw UsageError("reference needs --out FILE (.exr, or .png for final, ao and shadow)");
    const auto& names = reference::referenceBuffers();
    if (std::find(names.begin(), names.end(), buffer) == names.end())
        throw UsageError("--buffer: unknown reference buffer '" + buffer + "' (lbuffer, final, ao, shadow or spp_error)");
    const reference::PixelFilter pixelFilter = [&] {
        try {
            return reference::pixelFilterNamed(filter);
        } catch (const Error& e) {
            throw UsageError(e.what());
        }
    }();
    if (isFloatFormat(*out) && std::filesystem::path(*out).extension() != ".exr")
        throw UsageError("--out " + *out + ": float images are written as .exr (or .png for final, ao and shadow)");
    if (buffer == "lbuffer" && !isFloatFormat(*out))
        throw UsageError("--out " + *out + ": the L-buffer is HDR; write it as .exr");
    CommandLine::NamedFiles writes = {{"--out", *out}};
    if (statsOut) writes.emplace_back("--stats-out", *statsOut);
    CommandLine::requireDistinctFiles(writes, CommandLine::inputFiles(run));
    // A render can take minutes: an output that cannot be written fails now, not after it.
    for (const auto& [what, path] : writes) CommandLine::requireWritable(path, what + " file");

    run.validate();
    const Scene scene = loadScene(run.sceneSpec());
    for (const auto& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    KnobRegistry knobs = RunConfig::declaredKnobs();
    run.applyKnobs(knobs, scene);
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(knobs, scene);
    model.aoRays = aoRays;
    model.seed = static_cast<std::uint32_t>(seed);
    model.pixelSamples = spp;
    model.pixelFilter = pixelFilter;
    std::printf("%s\n", reference::reportKnobs(knobs, model, buffer == "final").text().c_str());

    reference::ReferenceRequest request;
    request.camera = run.camera(scene);
    request.width = run.width;
    request.height = run.height;
    request.threads = threads;

    const reference::ReferenceCache cache(cacheDir ? std::filesystem::path(*cacheDir) : std::filesystem::path());
    const std::string key = reference::referenceKey(scene, model, request);
    std::optional<reference::ReferenceImages> images;
    if (!noCache) images = cache.load(key);
    const bool cached = images.has_value();
    if (!cached) {
        try {
            images = renderWithProgress(scene, model, request, quiet);
        } catch (const reference::ReferenceCancelled&) {
            std::fprintf(stderr, "deferred-workbench: reference cancelled; nothing written or cached\n");
            return 130;
        }
        if (!noCache) {
            try {
                cache.store(key, *images);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "warning: the reference is not cached: %s\n", e.what());
            }
        }
    }
    writeImage(*out, *images->buffer(buffer));
    const reference::ReferenceStatistics& s = images->stats;
    std::printf("wrote %s (reference %s of a %dx%d frame, scene %s; %s)\n", out->c_str(), buffer.c_str(), run.width,
                run.height, scene.name.c_str(),
                cached ? ("from the cache, key " + key).c_str() : ("cache key " + key).c_str());
    std::printf("%s %.2f s on %d threads (Embree build %.2f s, %zu triangles): %.2f M rays (%.2f M rays/s; %lld primary, "
                "%lld shadow, %lld AO)\n",
                cached ? "rendered earlier in" : "rendered in", s.seconds, s.threads, s.buildSeconds, s.triangles,
                s.rays() / 1e6, s.seconds > 0 ? s.rays() / s.seconds / 1e6 : 0.0, s.primaryRays, s.shadowRays, s.aoRays);
    if (model.rayTracedAo)
        std::printf("ambient occlusion: %d rays per pixel, radius %g, standard error of A: mean %.4f, max %.4f\n",
                    model.aoRays, model.aoRadius, s.aoStandardErrorMean, s.aoStandardErrorMax);
    if (model.pixelSamples > 1) std::printf("%s\n", reference::pixelSamplesVerdict(*images, model).c_str());
    nlohmann::json stats = {{"key", key},
                            {"cached", cached},
                            {"scene", scene.name},
                            {"width", run.width},
                            {"height", run.height},
                            {"seconds", s.seconds},
                            {"build_seconds", s.buildSeconds},
                            {"threads", s.threads},
                            {"triangles", s.triangles},
                            {"primary_rays", s.primaryRays},
                            {"shadow_rays", s.shadowRays},
                            {"ao_rays", s.aoRays},
                            {"blended_hits", s.blendedHits},
                            {"ao_rays_per_pixel", model.rayTracedAo ? model.aoRays : 0},
                            {"ao_standard_error_mean", s.aoStandardErrorMean},
                            {"ao_standard_error_max", s.aoStandardErrorMax},
                            {"pixel_samples", model.pixelSamples},
                            {"pixel_filter", reference::pixelFilterName(model.pixelFilter)},
                            {"spp_error_mean", s.sppErrorMean},
                            {"spp_error_max", s.sppErrorMax},
                            {"model", model.canonical()}};
    if (throughput) {
        // Side by side in this run: the reference once more (uncached) and Embree alone over the same rays.
        const reference::ReferenceImages again = reference::renderReference(scene, model, request);
        const reference::RayThroughput bare = reference::measureRayThroughput(scene, model, request);
        const double refRate = again.stats.seconds > 0 ? again.stats.rays() / again.stats.seconds : 0.0;
        const double ratio = bare.raysPerSecond() > 0 ? refRate / bare.raysPerSecond() : 0.0;
        std::printf("throughput: reference %.2f M rays/s, Embree alone %.2f M rays/s over %.2f M rays: ratio %.2f\n",
                    refRate / 1e6, bare.raysPerSecond() / 1e6, bare.rays / 1e6, ratio);
        stats["throughput"] = {{"reference_rays_per_second", refRate},
                               {"embree_rays_per_second", bare.raysPerSecond()},
                               {"embree_rays", bare.rays},
                               {"ratio", ratio}};
    }
    if (statsOut) {
        std::ofstream f(*statsOut);
        f << stats.dump(2) << "\n";
        if (!f) throw FileError(*statsOut, "cannot write the statistics");
    }
    return 0;
}

}  // namespace dw
