// deferred-workbench render: one scene, one buffer, one image file.
#include <cstdio>
#include <iostream>
#include <tuple>

#include "app/CommandLine.h"
#include "app/Commands.h"
#include "app/HeadlessGlContext.h"
#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

void printTimings(Pipeline& pipeline, const FrameReport& last, int frames) {
    PassTimer& timer = pipeline.timer();
    timer.collect(true);
    std::printf("%-16s %14s %14s %14s %14s  %s\n", "pass", "GPU median ms", "GPU min ms", "GPU max ms", "CPU median ms",
                "frames");
    for (const auto& rec : last.passes) {
        if (!rec.ran) {
            std::printf("%-16s %14s  (skipped: %s)\n", rec.name.c_str(), "-", rec.reason.c_str());
            continue;
        }
        const TimingStats g = timer.gpuStats(rec.name, static_cast<size_t>(frames));
        const TimingStats c = timer.cpuStats(rec.name, static_cast<size_t>(frames));
        std::printf("%-16s %14.3f %14.3f %14.3f %14.3f  %d\n", rec.name.c_str(), g.median, g.min, g.max, c.median, g.count);
        // Parts of the pass with their own spans (e.g. lighting/shadow maps).
        for (const auto& series : timer.series()) {
            if (series.name.rfind(rec.name + "/", 0) != 0) continue;
            const TimingStats sg = timer.gpuStats(series.name, static_cast<size_t>(frames));
            const TimingStats sc = timer.cpuStats(series.name, static_cast<size_t>(frames));
            std::printf("  %-14s %14.3f %14.3f %14.3f %14.3f  %d\n", series.name.substr(rec.name.size() + 1).c_str(), sg.median,
                        sg.min, sg.max, sc.median, sg.count);
        }
        if (!rec.stats.empty()) std::printf("  (%s)\n", rec.stats.c_str());
    }
    const TimingStats g = timer.gpuStats(PassTimer::kFrameSeries, static_cast<size_t>(frames));
    const TimingStats c = timer.cpuStats(PassTimer::kFrameSeries, static_cast<size_t>(frames));
    std::printf("%-16s %14.3f %14.3f %14.3f %14.3f  %d\n", "frame (total)", g.median, g.min, g.max, c.median, g.count);
}

}  // namespace

int runRenderCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2);
    if (cl.flag("--help")) {
        std::cout << "usage: deferred-workbench render [--scene NAME|FILE] [--size WxH] [--buffer NAME]\n"
                     "                                 [--preset NAME|FILE] [--set knob=value]... [--frames N] [--timings]\n"
                     "                                 [--dump-knobs FILE] --out FILE\n"
                     "  --scene      built-in scene (default), a scene .json, or a .gltf/.glb file\n"
                     "  --preset     a built-in preset (list presets) or a preset .json; its knobs apply after\n"
                     "               the scene's settings and before --set; its scene is used without --scene\n"
                     "  --buffer     any named output (list buffers); default: final\n"
                     "  --out        .png writes the displayed (8-bit) view; .exr the raw float values\n"
                     "  --frames     frames to render (timings are medians over them); default 1\n"
                     "  --timings    print per-pass GPU and CPU milliseconds\n"
                     "  --dump-knobs write every knob's value as name=value lines (what --set takes)\n";
        return 0;
    }
    RunConfig run = cl.runConfig();
    std::tie(run.width, run.height) = CommandLine::parseSize(cl.value("--size").value_or("1280x720"));
    run.frames = CommandLine::parseInt("--frames", cl.value("--frames").value_or("1"), 1, 100000);
    const std::string buffer = cl.value("--buffer").value_or("final");
    const auto out = cl.value("--out");
    const auto dumpKnobs = cl.value("--dump-knobs");
    const bool timings = cl.flag("--timings");
    const bool verbose = cl.flag("--verbose");
    cl.finish("render");
    if (!cl.positional().empty()) throw UsageError("render: unexpected argument '" + cl.positional()[0] + "'");
    if (!out) throw UsageError("render needs --out FILE (.png or .exr)");

    // Bad input fails before any GL work: the preset and --set against the
    // knob declarations, then the scene (CPU only).
    run.validate();
    Scene loaded = loadScene(run.sceneSpec());

    auto context = HeadlessGlContext::create();
    RenderSession session;
    if (verbose)
        std::fprintf(stderr, "GL: %s | %s (%s)\n", session.glInfo().renderer.c_str(), session.glInfo().version.c_str(),
                     context->platform().c_str());
    session.setScene(std::move(loaded), run);
    for (const auto& w : session.scene().warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    session.resize(run.width, run.height);
    FrameRequest request;
    request.outputs = {buffer};
    FrameReport report;
    for (int i = 0; i < run.frames; ++i) report = session.render(request);
    session.writeOutput(buffer, *out);
    std::printf("wrote %s (%dx%d, %s, scene %s)\n", out->c_str(), run.width, run.height, buffer.c_str(),
                session.scene().name.c_str());
    if (dumpKnobs) session.writeKnobValues(*dumpKnobs);
    if (timings) printTimings(session.pipeline(), report, run.frames);
    return 0;
}

}  // namespace dw
