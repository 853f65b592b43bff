// deferred-workbench reference: the CPU ground truth of one view, headless,
// with no GL at all (renderer/reference/ReferenceRenderer.h).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <tuple>

#include "app/Commands.h"
#include "app/ReferenceProgressLine.h"
#include "headless/CommandLine.h"
#include "renderer/Error.h"
#include "renderer/reference/ReferenceCache.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/scene/ClipChoice.h"
#include "renderer/scene/SceneLoader.h"
#include "renderer/scene/ScenePose.h"

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

// reference's options, read and checked before anything is traced.
struct ReferenceOptions {
    RunConfig run;
    std::string buffer, out;
    int aoRays = 64, seed = 1, spp = 1, threads = 0;
    reference::PixelFilter filter = reference::PixelFilter::Box;
    bool noCache = false, throughput = false, quiet = false;
    std::optional<std::string> cacheDir, statsOut;
};

void printUsage() {
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
               "  --animation  which glTF animation clip plays: a clip's name or index (0-based over the scene's\n"
               "               clips), or none; default each file's first (docs/scene-format.md, \"Animation\")\n"
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
}

// The buffer, the image formats and the files: usage errors before the trace.
void checkOptions(const ReferenceOptions& o) {
    const auto& names = reference::referenceBuffers();
    if (std::find(names.begin(), names.end(), o.buffer) == names.end())
        throw UsageError("--buffer: unknown reference buffer '" + o.buffer + "' (lbuffer, final, ao, shadow or spp_error)");
    if (isFloatFormat(o.out) && std::filesystem::path(o.out).extension() != ".exr")
        throw UsageError("--out " + o.out + ": float images are written as .exr (or .png for final, ao and shadow)");
    if (o.buffer == "lbuffer" && !isFloatFormat(o.out))
        throw UsageError("--out " + o.out + ": the L-buffer is HDR; write it as .exr");
    CommandLine::NamedFiles writes = {{"--out", o.out}};
    if (o.statsOut) writes.emplace_back("--stats-out", *o.statsOut);
    CommandLine::requireDistinctFiles(writes, CommandLine::inputFiles(o.run));
    // A render can take minutes: an output that cannot be written fails now, not after it.
    for (const auto& [what, path] : writes) CommandLine::requireWritable(path, what + " file");
}

ReferenceOptions readOptions(CommandLine& cl) {
    ReferenceOptions o;
    o.run = cl.runConfig();
    o.run.sceneTime = cl.real("--scene-time").value_or(0.0);
    std::tie(o.run.width, o.run.height) = cl.size().value_or(std::pair{1280, 720});
    o.buffer = cl.value("--buffer").value_or("lbuffer");
    const auto out = cl.value("--out");
    o.aoRays = cl.whole("--ao-rays", 64);
    o.seed = cl.whole("--seed", 1);
    o.spp = cl.whole("--spp", 1);
    const std::string filter = cl.value("--filter").value_or("box");
    const int requestedThreads = cl.whole("--threads", 0);
    // oneTBB runs at most as many threads as the machine has cores; more are not asked for.
    o.threads = requestedThreads > 0 ? std::min(requestedThreads, reference::availableThreads()) : 0;
    if (requestedThreads > o.threads && o.threads > 0)
        std::fprintf(stderr, "note: --threads %d: this machine runs %d at once; using %d\n", requestedThreads, o.threads,
                     o.threads);
    o.noCache = cl.flag("--no-cache");
    o.cacheDir = cl.value("--cache-dir");
    o.statsOut = cl.value("--stats-out");
    o.throughput = cl.flag("--throughput");
    o.quiet = cl.flag("--quiet");
    cl.finish("reference");
    if (!cl.positional().empty()) throw UsageError("reference: unexpected argument '" + cl.positional()[0] + "'");
    if (!out) throw UsageError("reference needs --out FILE (.exr, or .png for final, ao and shadow)");
    o.out = *out;
    try {
        o.filter = reference::pixelFilterNamed(filter);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    checkOptions(o);
    if (o.spp == 1 && o.filter != reference::PixelFilter::Box)
        std::fprintf(stderr, "note: --filter %s does nothing at --spp 1 (one sample, at the pixel's centre)\n", filter.c_str());
    if (o.spp == 1 && o.buffer == "spp_error")
        std::fprintf(stderr, "note: spp_error is 0 at --spp 1: one sample has no spread\n");
    return o;
}

// The images of the view: from the cache, or traced (with progress) and stored.
// Nothing when the trace was cancelled.
std::optional<reference::ReferenceImages> tracedOrCached(const ReferenceOptions& o, const Scene& scene,
                                                         const reference::ReferenceModel& model,
                                                         const reference::ReferenceRequest& request,
                                                         const std::string& key, bool& cached) {
    const reference::ReferenceCache cache(o.cacheDir ? std::filesystem::path(*o.cacheDir) : std::filesystem::path());
    std::optional<reference::ReferenceImages> images;
    if (!o.noCache) images = cache.load(key);
    cached = images.has_value();
    if (cached) return images;
    try {
        images = renderWithProgress(scene, model, request, o.quiet);
    } catch (const reference::ReferenceCancelled&) {
        return std::nullopt;
    }
    if (!o.noCache) {
        try {
            cache.store(key, *images);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "warning: the reference is not cached: %s\n", e.what());
        }
    }
    return images;
}

// What the run prints after the image is written.
void printReport(const ReferenceOptions& o, const Scene& scene, const reference::ReferenceModel& model,
                 const reference::ReferenceImages& images, const std::string& key, bool cached) {
    const reference::ReferenceStatistics& s = images.stats;
    std::printf("wrote %s (reference %s of a %dx%d frame, scene %s; %s)\n", o.out.c_str(), o.buffer.c_str(), o.run.width,
                o.run.height, scene.name.c_str(),
                cached ? ("from the cache, key " + key).c_str() : ("cache key " + key).c_str());
    std::printf("%s %.2f s on %d threads (Embree build %.2f s, %zu triangles): %.2f M rays (%.2f M rays/s; %lld primary, "
                "%lld shadow, %lld AO)\n",
                cached ? "rendered earlier in" : "rendered in", s.seconds, s.threads, s.buildSeconds, s.triangles,
                s.rays() / 1e6, s.seconds > 0 ? s.rays() / s.seconds / 1e6 : 0.0, s.primaryRays, s.shadowRays, s.aoRays);
    if (model.rayTracedAo && model.aoRays < 2)
        std::printf("ambient occlusion: 1 ray per pixel sample, radius %g, standard error of A: not estimated (one "
                    "ray a sample has no spread; --ao-rays 2 or more)\n", model.aoRadius);
    else if (model.rayTracedAo)
        std::printf("ambient occlusion: %d rays per pixel, radius %g, standard error of A: mean %.4f, max %.4f\n",
                    model.aoRays, model.aoRadius, s.aoStandardErrorMean, s.aoStandardErrorMax);
    if (model.pixelSamples > 1) std::printf("%s\n", reference::pixelSamplesVerdict(images, model).c_str());
}

// --stats-out's JSON (and --throughput's figures, measured side by side here).
nlohmann::json statistics(const ReferenceOptions& o, const Scene& scene, const reference::ReferenceModel& model,
                          const reference::ReferenceRequest& request, const reference::ReferenceImages& images,
                          const std::string& key, bool cached) {
    const reference::ReferenceStatistics& s = images.stats;
    nlohmann::json stats = {{"key", key},
                            {"cached", cached},
                            {"scene", scene.name},
                            {"width", o.run.width},
                            {"height", o.run.height},
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
                            {"spp_relative_error_mean", reference::meanRelativeSppError(images)},
                            {"spp_enough", reference::meanRelativeSppError(images) < reference::kSppEnough},
                            {"model", model.canonical()}};
    if (o.throughput) {
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
    return stats;
}

}  // namespace

int runReferenceCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2, "reference");
    if (cl.flag("--help")) {
        printUsage();
        return 0;
    }
    const ReferenceOptions o = readOptions(cl);
    RunConfig run = o.run;
    run.validate();
    Scene scene = loadScene(run.sceneSpec());
    chooseClip(scene.animation, run.animation);  // --animation, as RenderSession::setScene
    poseScene(scene, run.sceneTime);             // the pose the GPU renders at --scene-time
    for (const auto& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    KnobRegistry knobs = RunConfig::declaredKnobs();
    run.applyKnobs(knobs, scene);
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(knobs, scene);
    model.aoRays = o.aoRays;
    model.seed = static_cast<std::uint32_t>(o.seed);
    model.pixelSamples = o.spp;
    model.pixelFilter = o.filter;
    std::printf("%s\n", reference::reportKnobs(knobs, model, o.buffer == "final").text().c_str());

    reference::ReferenceRequest request;
    request.camera = run.camera(scene);
    request.width = run.width;
    request.height = run.height;
    request.threads = o.threads;
    const std::string key = reference::referenceKey(scene, model, request);
    bool cached = false;
    const std::optional<reference::ReferenceImages> images = tracedOrCached(o, scene, model, request, key, cached);
    if (!images) {
        std::fprintf(stderr, "deferred-workbench: reference cancelled; nothing written or cached\n");
        return 130;
    }
    writeImage(o.out, *images->buffer(o.buffer));
    printReport(o, scene, model, *images, key, cached);
    const nlohmann::json stats = statistics(o, scene, model, request, *images, key, cached);
    if (o.statsOut) {
        std::ofstream f(*o.statsOut);
        f << stats.dump(2) << "\n";
        if (!f) throw FileError(*o.statsOut, "cannot write the statistics");
    }
    return 0;
}

}  // namespace dw
