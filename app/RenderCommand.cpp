// deferred-workbench render: one scene, one buffer, one image file.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "app/Commands.h"
#include "app/CompareSequence.h"
#include "app/RenderSequence.h"
#include "renderer/passes/AaMethod.h"
#include "renderer/record/ExperimentRecord.h"
#include "app/ReferenceProgressLine.h"
#include "app/RenderDocCapture.h"
#include "headless/CommandLine.h"
#include "headless/HeadlessGlContext.h"
#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/ao/AovCostEstimate.h"
#include "renderer/graph/TimingReport.h"
#include "renderer/inspect/FiniteCheck.h"
#include "renderer/inspect/MemoryTable.h"
#include "renderer/reference/ViewReference.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

void printUsage() {
    std::cout << "usage: deferred-workbench render [--scene NAME|FILE] [--size WxH] [--buffer NAME]\n"
                     "                                 [--preset NAME|FILE]... [--set knob=value]... [--dump-knobs FILE]\n"
                     "                                 [--frames N] [--warmup N] [--timings] [--timings-out FILE]\n"
                     "                                 [--renderdoc-capture FILE.rdc] [--check-finite] [--record FILE]\n"
                     "                                 [--ao-rays N] [--seed N] [--spp N] [--threads N] [--no-cache]\n"
                     "                                 [--cache-dir DIR] [--memory]\n"
                     "                                 --out FILE | [--orbit N [--orbit-degrees D] | --walkthrough |\n"
                     "                                 --time-steps N [--frame-rate F]]\n"
                     "                                 --out-sequence PATTERN\n"
                     "  --scene      built-in scene (default), a scene .json, or a .gltf/.glb file\n"
                     "  --animation  which glTF animation clip plays: a clip's name or index (0-based over the scene's\n"
                     "               clips), or none; default each file's first (docs/scene-format.md, \"Animation\")\n"
                     "  --preset     a built-in preset (list presets) or a preset .json; its knobs apply after\n"
                     "               the scene's settings and before --set; its scene is used without --scene;\n"
                     "               repeated, each applies in the order given, a later one's knobs winning\n"
                     "  --buffer     any named output (list buffers); default: final. reference.lbuffer,\n"
                     "               reference.final, reference.ao and compare.error first trace the CPU reference of\n"
                     "               the view as `reference` does (the scene as the last frame has it; progress on\n"
                     "               stderr, Ctrl+C cancels with exit 130) and hand it to the reference pass\n"
                     "  --ao-rays, --seed, --spp, --threads, --no-cache, --cache-dir  that trace's options, as\n"
                     "               `reference` takes them (defaults 64, 1, 1, every core, the cache); only with those\n"
                     "               buffers (reference.spp_error is 0 at --spp 1: one sample has no spread)\n"
                     "  --out        .png writes the displayed (8-bit) view; .exr the raw float values\n"
                     "  --out-sequence  a camera path's frames, rendered in order by one session (a temporal\n"
                     "               method's history carried), after --warmup frames at the first camera;\n"
                     "               frame k to PATTERN's file k (one integer conversion: f%03d.png), as\n"
                     "               compare --sequence reads them; a reference buffer is traced per camera\n"
                     "  --time-steps N  N frames at the scene's camera, frame k at --scene-time + k / F seconds\n"
                     "               (--frame-rate F, default 30): an animated scene's sequence\n"
                     "  --orbit N    N cameras on a circle about the scene's camera, --orbit-degrees D apart\n"
                     "               D / N degrees (default 360); --walkthrough: the scene's camera.path keyframes\n"
                     "  --frames     frames counted (timings are medians over them); default 1\n"
                     "  --warmup     frames rendered first and left out of the timings; default 1 when\n"
                     "               timings are asked for (the first frame compiles shaders), else 0\n"
                     "  --timings    print per-pass GPU and CPU milliseconds, and each pass's cost counters\n"
                     "               (fragments, samples, primitives, vertices, compute, bytes)\n"
                     "  --timings-out  write the timings as .json, or as .csv rows (any other name)\n"
                     "  --dump-knobs write every knob's value as name=value lines (what --set takes)\n"
                     "  --renderdoc-capture  capture the last frame with RenderDoc (loads librenderdoc.so,\n"
                     "               Debian package librenderdoc); RenderDoc writes FILE_capture.rdc\n"
                     "  --record     write an experiment record (JSON): scene and the sha256 of its files, camera,\n"
                     "               every knob, size, frames, build, GL, CPU, each counted frame's timings and\n"
                     "               the image's sha256; `replay FILE` measures it again (a CPU reference buffer:\n"
                     "               with the record's --ao-rays and --seed, traced again through the cache)\n"
                     "  --memory     print the GPU memory table after the last frame (the inspector's): each\n"
                     "               frame-graph resource and each owner of what passes, services and the scene\n"
                     "               allocated (shadow maps, light lists, taa history ...), the total and the peak\n"
                     "  --check-finite  read back every buffer the last frame produced, in pipeline order; exit 3\n"
                     "               naming the first that holds a NaN or an infinity (and its first pixel)\n"
              << CommandLine::rangesHelp("render");
}

// render's options, read and checked (files distinct and writable) before anything renders.
struct RenderOptions {
    RunConfig run;
    std::string buffer, out;
    std::optional<std::string> dumpKnobs, timingsOut, renderdocCapture, record;
    bool timings = false, timed = false, verbose = false, checkFinite = false, memory = false;
    // The CPU reference's options (as `reference` takes them), for the reference pass's outputs.
    reference::ViewReferenceOptions reference;
    bool referenceOptionGiven = false;
    RenderSequence sequence;  // --out-sequence along --orbit or --walkthrough
};

void readReferenceOptions(CommandLine& cl, RenderOptions& o) {
    const auto aoRaysGiven = cl.whole("--ao-rays");
    const auto seedGiven = cl.whole("--seed");
    const auto sppGiven = cl.whole("--spp");
    const auto threadsGiven = cl.whole("--threads");
    const bool noCache = cl.flag("--no-cache");
    const auto cacheDir = cl.value("--cache-dir");
    o.reference.aoRays = aoRaysGiven.value_or(64);
    o.reference.seed = seedGiven.value_or(1);
    o.reference.pixelSamples = sppGiven.value_or(1);
    o.reference.threads = threadsGiven.value_or(0);
    o.reference.useCache = !noCache;
    o.reference.cacheDirectory = cacheDir.value_or("");
    o.reference.cacheWarning = [](const std::string& why) {
        std::fprintf(stderr, "warning: the reference is not cached: %s\n", why.c_str());
    };
    o.referenceOptionGiven = aoRaysGiven || seedGiven || sppGiven || threadsGiven || noCache || cacheDir;
}

// --out-sequence: its frames are its only output; frame 0's file writable.
RenderOptions checkSequenceOptions(RenderOptions o, const std::optional<std::string>& out) {
    if (out) throw UsageError("--out-sequence writes the frames; give it without --out");
    if (o.timed || o.record || o.renderdocCapture || o.checkFinite || o.dumpKnobs || o.run.frames != 1)
        throw UsageError("--out-sequence renders one frame a camera: it takes no --frames, --timings, "
                         "--timings-out, --record, --renderdoc-capture, --check-finite or --dump-knobs");
    CommandLine::requireDistinctFiles({{"--out-sequence", sequenceFrameName(o.sequence.pattern, 0)}},
                                      CommandLine::inputFiles(o.run));
    CommandLine::requireWritable(sequenceFrameName(o.sequence.pattern, 0), "--out-sequence file");
    return o;
}

RenderOptions readOptions(CommandLine& cl) {
    RenderOptions o;
    o.run = cl.runConfig();
    o.run.sceneTime = cl.real("--scene-time").value_or(0.0);
    std::tie(o.run.width, o.run.height) = cl.size().value_or(std::pair{1280, 720});
    o.run.frames = cl.whole("--frames", 1);
    o.buffer = cl.value("--buffer").value_or("final");
    const auto out = cl.value("--out");
    o.dumpKnobs = cl.value("--dump-knobs");
    o.timings = cl.flag("--timings");
    o.timingsOut = cl.value("--timings-out");
    // Only counted frames are measured, so warm-up matters only when timing.
    o.timed = o.timings || o.timingsOut;
    o.run.warmup = cl.whole("--warmup", o.timed ? 1 : 0);
    o.verbose = cl.flag("--verbose");
    o.renderdocCapture = cl.value("--renderdoc-capture");
    o.checkFinite = cl.flag("--check-finite");
    o.memory = cl.flag("--memory");
    o.record = cl.value("--record");
    readReferenceOptions(cl, o);
    o.sequence = RenderSequence::read(cl);
    cl.finish("render");
    if (!cl.positional().empty()) throw UsageError("render: unexpected argument '" + cl.positional()[0] + "'");
    if (o.sequence.given()) return checkSequenceOptions(o, out);
    if (!out) throw UsageError("render needs --out FILE (.png or .exr)");
    o.out = *out;
    // No output may replace another, or the scene or preset it renders.
    CommandLine::NamedFiles writes = {{"--out", o.out}};
    if (o.timingsOut) writes.emplace_back("--timings-out", *o.timingsOut);
    if (o.dumpKnobs) writes.emplace_back("--dump-knobs", *o.dumpKnobs);
    if (o.record) writes.emplace_back("--record", *o.record);
    CommandLine::requireDistinctFiles(writes, CommandLine::inputFiles(o.run));
    // An output that cannot be written fails now, not after the frames (a
    // --record in a missing folder used to fail after --out was written).
    for (const auto& [what, path] : writes) CommandLine::requireWritable(path, what + " file");
    return o;
}

// RenderDoc must be loaded before the GL context exists, to hook it.
RenderDocCapture startRenderDoc(char** argv, const std::string& capture) {
    if (const std::string why = RenderDocCapture::relaunchUnderRenderDoc(argv); !why.empty())
        throw Error("--renderdoc-capture: " + why);
    RenderDocCapture renderdoc = RenderDocCapture::attach(false);
    if (!renderdoc.available()) throw Error("--renderdoc-capture: " + renderdoc.why());
    std::string stem = capture;
    if (stem.size() > 4 && stem.compare(stem.size() - 4, 4, ".rdc") == 0) stem.resize(stem.size() - 4);
    renderdoc.setPathTemplate(stem);
    return renderdoc;
}

// AOV's cost estimated from the triangles before the first frame (issue 22).
void warnAovCost(RenderSession& session, const RunConfig& run, bool verbose) {
    const auto estimateStart = std::chrono::steady_clock::now();
    if (const auto e = AovCostEstimate::forKnobs(session.knobs(), session.scene(), session.camera(), run.width,
                                                 run.height)) {
        if (verbose)
            std::fprintf(stderr, "aov: estimated %.2f volume fragments per pixel (%zu volumes, %zu culled, %zu reaching "
                                 "the near plane, radius %.4g; estimated in %.3f s)\n",
                         e->meanOverdraw, e->volumes, e->culled, e->nearCamera, e->radius,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - estimateStart).count());
        if (const std::string w = AovCostEstimate::warning(*e, session.knobs(), run.width, run.height); !w.empty())
            std::fprintf(stderr, "warning: %s\n", w.c_str());
    }
}

// The reference of the view as the last frame has it (flame particles move
// with the frame index), traced as `reference` does, then handed to the
// reference pass for these frames: what Python's Session.render(buffer) does,
// so both give the same image bit for bit. False when it was cancelled.
bool traceAndShowReference(RenderSession& session, const RenderOptions& o) {
    const RunConfig& run = o.run;
    if (o.reference.threads > reference::availableThreads())
        std::fprintf(stderr, "note: --threads %d: this machine runs %d at once; using %d\n", o.reference.threads,
                     reference::availableThreads(), reference::availableThreads());
    const std::uint64_t lastFrame =
        session.pipeline().frameIndex() + static_cast<std::uint64_t>(run.warmup + run.frames - 1);
    reference::ViewReference traced;
    try {
        traceWithProgressLine(
            [&](reference::ReferenceProgress* progress) {
                reference::ViewReferenceOptions ro = o.reference;
                ro.progress = progress;
                traced = reference::traceViewReference(session.scene(), session.knobs(), session.camera(), run.width,
                                                       run.height, ro, lastFrame);
            },
            run.width, run.height, false);
    } catch (const reference::ReferenceCancelled&) {
        return false;
    }
    const reference::ReferenceStatistics& s = traced.images.stats;
    std::printf("CPU reference of the view: %d AO rays per pixel, seed %d; %s %.2f s on %d threads (cache key %s)\n",
                traced.model.rayTracedAo ? traced.model.aoRays : 0, o.reference.seed,
                traced.cached ? "from the cache, rendered earlier in" : "rendered in", s.seconds, s.threads,
                traced.key.c_str());
    session.showReference(&traced.images);
    return true;
}

// Warm-up and counted frames (the last one captured by RenderDoc when asked);
// `firstCounted` the first counted frame's index.
FrameReport renderFrames(RenderSession& session, const RenderOptions& o, RenderDocCapture& renderdoc,
                         std::uint64_t& firstCounted) {
    FrameRequest request;
    request.outputs = {o.buffer};
    // Keep every counted frame's sample, however many there are.
    PassTimer& timer = session.pipeline().timer();
    timer.setHistoryLength(std::max<size_t>(PassTimer::kHistory, static_cast<size_t>(o.run.warmup + o.run.frames)));
    // Timings and records come with each pass's cost counters (PassCounts.h).
    if (o.timed || o.record) timer.setCounting(true);
    FrameReport report;
    for (int i = 0; i < o.run.warmup + o.run.frames; ++i) {
        // The last frame is the one captured.
        const bool capture = renderdoc.available() && i + 1 == o.run.warmup + o.run.frames;
        if (capture) renderdoc.startFrameCapture();
        report = session.render(request);
        if (capture && (!renderdoc.endFrameCapture() || renderdoc.lastCapturePath().empty()))
            throw Error("--renderdoc-capture: RenderDoc recorded no frame");
        if (i == o.run.warmup) firstCounted = report.frameIndex;
    }
    if (renderdoc.available()) std::printf("wrote %s (RenderDoc capture of the last frame)\n", renderdoc.lastCapturePath().c_str());
    return report;
}

// --check-finite: every produced buffer, not only the one written: the first
// named is the earliest pass that made a non-finite value. False when one does.
bool allFinite(RenderSession& session) {
    const std::vector<NonFiniteCount> counts = FiniteCheck::scan(session.pipeline().outputs());
    for (const NonFiniteCount& c : counts) {
        if (c.nonFinite() == 0) continue;
        std::fprintf(stderr,
                     "error: buffer '%s' holds %lld non-finite values (%lld NaN, %lld +Inf, %lld -Inf); the first at "
                     "pixel (%d, %d), rows top-down\n",
                     c.buffer.c_str(), c.nonFinite(), c.nan, c.positiveInf, c.negativeInf, c.firstX, c.firstY);
        return false;
    }
    std::printf("check-finite: %zu buffers, no NaN or infinity\n", counts.size());
    return true;
}

// The image, the lost-fragment warnings, --dump-knobs, --record, --check-finite and the timings.
int writeResults(RenderSession& session, const RenderOptions& o, const FrameReport& report, std::uint64_t firstCounted,
                 const std::string& platform, bool needsReference) {
    session.writeOutput(o.buffer, o.out);
    std::printf("wrote %s (%s of a %dx%d frame, scene %s)\n", o.out.c_str(), o.buffer.c_str(), o.run.width,
                o.run.height, session.scene().name.c_str());
    // What a pass lost in the frame written (the oit pass's fragments), one line each.
    for (const auto& w : report.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (o.dumpKnobs) session.writeKnobValues(*o.dumpKnobs);
    if (o.record) {
        ExperimentRecord r = ExperimentRecord::capture(session, o.run, o.buffer, firstCounted, platform);
        // A reference buffer: the trace's rays and seed, so replay traces the same reference.
        if (needsReference) r.setReference(o.reference.aoRays, static_cast<std::uint32_t>(o.reference.seed), o.reference.pixelSamples,
                                         reference::pixelFilterName(o.reference.pixelFilter));
        r.write(*o.record);
        std::printf("wrote %s (experiment record; deferred-workbench replay %s measures it again)\n", o.record->c_str(),
                    o.record->c_str());
    }
    if (o.memory) std::fputs(MemoryTable::build(session.pipeline().resources()).text().c_str(), stdout);
    if (o.checkFinite && !allFinite(session)) return 3;
    if (o.timed) {
        const TimingReport t = TimingReport::build(session.pipeline().timer(), report, firstCounted, o.run.warmup);
        if (o.timings) std::fputs(t.table().c_str(), stdout);
        if (o.timingsOut) t.write(*o.timingsOut);
    }
    return 0;
}

// The reference pass's buffers are the output size and SSAA renders the
// frame at aa.ssaa_factor times it: refused before anything is traced (the
// trace would be thrown away when the frame fails), naming both sizes.
void refuseReferenceUnderSsaa(const RenderSession& session, const RenderOptions& o) {
    const std::optional<int> method = session.knobs().find(kAaMethodKnob);
    if (!method || session.knobs().format(*method) != "ssaa") return;
    const std::optional<int> factor = session.knobs().find("aa.ssaa_factor");
    const std::string f = factor ? session.knobs().format(*factor) : "2";
    throw UsageError("render: --buffer " + o.buffer + " is the CPU reference at the output size (" +
                     std::to_string(o.run.width) + "x" + std::to_string(o.run.height) +
                     ") and aa.method=ssaa renders the frame at " + f + "x" + f +
                     " that size: set aa.method to another method for the reference's buffers (the reference "
                     "is its own anti-aliasing: --spp N)");
}

// --out-sequence: the path's cameras in order, one frame each after --warmup
// frames at the first; a reference buffer traced per camera. 130 when cancelled.
int renderSequenceFrames(RenderSession& session, RenderOptions o, bool needsReference) {
    const std::vector<Camera> cameras = o.sequence.cameras(session.camera(), session.scene());
    const FrameRequest request{{o.buffer}};
    const double start = session.sceneTime();
    session.camera() = cameras.front();
    for (int i = 0; i < o.run.warmup; ++i) session.render(request);
    o.run.warmup = 0;  // what traceAndShowReference counts: this frame alone
    for (size_t k = 0; k < cameras.size(); ++k) {
        session.camera() = cameras[k];
        session.setSceneTime(o.sequence.sceneTime(start, k));
        if (needsReference && !traceAndShowReference(session, o)) {
            std::fprintf(stderr, "deferred-workbench: reference cancelled; frames before %zu written\n", k);
            return 130;
        }
        const FrameReport report = session.render(request);
        session.writeOutput(o.buffer, sequenceFrameName(o.sequence.pattern, static_cast<int>(k)));
        for (const auto& w : report.warnings()) std::fprintf(stderr, "warning: frame %zu: %s\n", k, w.c_str());
    }
    std::printf(o.sequence.timeSteps > 0 ? "wrote %s, frames 0..%zu (%s of %dx%d frames over scene time, scene %s)\n"
                                         : "wrote %s, frames 0..%zu (%s of %dx%d frames along the camera path, scene %s)\n",
                o.sequence.pattern.c_str(), cameras.size() - 1, o.buffer.c_str(), o.run.width, o.run.height,
                session.scene().name.c_str());
    return 0;
}

}  // namespace

int runRenderCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2, "render");
    if (cl.flag("--help")) {
        printUsage();
        return 0;
    }
    const RenderOptions o = readOptions(cl);
    // Bad input fails before any GL work: the preset and --set against the
    // knob declarations, then the scene (CPU only).
    o.run.validate();
    Scene loaded = loadScene(o.run.sceneSpec());
    RenderDocCapture renderdoc;
    if (o.renderdocCapture) renderdoc = startRenderDoc(argv, *o.renderdocCapture);
    auto context = HeadlessGlContext::create();
    RenderSession session;
    if (o.verbose)
        std::fprintf(stderr, "GL: %s | %s (%s)\n", session.glInfo().renderer.c_str(), session.glInfo().version.c_str(),
                     context->platform().c_str());
    session.setScene(std::move(loaded), o.run);
    for (const auto& w : session.scene().warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    session.resize(o.run.width, o.run.height);
    const bool needsReference = session.isReferenceOutput(o.buffer);
    if (!needsReference && o.referenceOptionGiven)
        throw UsageError("render: --ao-rays, --seed, --spp, --threads, --no-cache and --cache-dir are the CPU reference's "
                         "options, for reference.lbuffer, reference.final, reference.ao, reference.spp_error and "
                         "compare.error; --buffer " +
                         o.buffer + " has no reference");
    if (needsReference) refuseReferenceUnderSsaa(session, o);
    warnAovCost(session, o.run, o.verbose);
    if (needsReference && !o.sequence.given() && !traceAndShowReference(session, o)) {
        std::fprintf(stderr, "deferred-workbench: reference cancelled; nothing written or cached\n");
        return 130;
    }
    if (o.sequence.given()) return renderSequenceFrames(session, o, needsReference);
    std::uint64_t firstCounted = 0;
    const FrameReport report = renderFrames(session, o, renderdoc, firstCounted);
    return writeResults(session, o, report, firstCounted, context->platform(), needsReference);
}

}  // namespace dw
