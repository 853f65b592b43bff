// deferred-workbench replay RECORD.json: restores the state an experiment
// record holds (scene, camera, every knob, size, frames, warm-up), renders and
// measures again, and says what changed: the image (sha256 of its pixels), each
// scene file, knob and build field by name, and each timing series old
// against new with the bootstrap interval of the ratio of medians.
// Exit 0: the image is identical; 1: it differs; 2: the record is refused.
#include <cstdio>
#include <iostream>
#include <map>

#include "app/CommandLine.h"
#include "app/Commands.h"
#include "app/ExperimentRecord.h"
#include "app/HeadlessGlContext.h"
#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/bench/Bootstrap.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

std::string shortHash(const std::string& h) { return h.empty() ? "unreadable" : h.substr(0, 16); }

}  // namespace

int runReplayCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2);
    if (cl.flag("--help")) {
        std::cout << "usage: deferred-workbench replay RECORD.json [--record FILE]\n"
                     "Restores the state of an experiment record (render --record), renders and measures again, and\n"
                     "prints 'image: identical' or 'image: differs (sha256 old -> new)', each changed scene file,\n"
                     "knob and build field by name, and old against new timings with the 95% interval of each ratio.\n"
                     "  --record     write the new run's record too\n"
                     "Exit 0: the image is identical; 1: it differs; 2: the record is refused.\n";
        return 0;
    }
    const auto newRecord = cl.value("--record");
    cl.finish("replay");
    if (cl.positional().size() != 1) throw UsageError("replay needs one record file: deferred-workbench replay RECORD.json");
    const std::string path = cl.positional()[0];

    ExperimentRecord old;
    try {
        old = ExperimentRecord::read(path);
    } catch (const Error& e) {
        std::fprintf(stderr, "refused: %s\n", e.what());
        return 2;
    }

    // Scene files by name: the content the record measured against this one's.
    for (const RecordedFile& f : old.sceneFiles) {
        const std::string now = ExperimentRecord::sha256OfFile(f.path);
        if (now != f.sha256)
            std::printf("scene file changed: %s (sha256 %s -> %s)\n", f.path.c_str(), shortHash(f.sha256).c_str(),
                        shortHash(now).c_str());
    }
    // Knobs: every recorded value restored; those this build lacks or adds are named.
    const KnobRegistry declared = RunConfig::declaredKnobs();
    RunConfig run;
    run.scene = old.sceneSpec;
    run.width = old.width;
    run.height = old.height;
    run.frames = old.frames;
    run.warmup = old.warmup;
    std::map<std::string, std::string> recorded(old.knobs.begin(), old.knobs.end());
    for (const auto& [name, value] : old.knobs) {
        if (!declared.find(name)) {
            std::printf("knob not in this build: %s (recorded %s)\n", name.c_str(), value.c_str());
            continue;
        }
        KnobRegistry probe = declared;
        try {
            probe.setFromString(name, value);
        } catch (const Error& e) {
            std::printf("knob value refused by this build: %s\n", e.what());
            continue;
        }
        run.sets.push_back(name + "=" + value);
    }
    for (size_t i = 0; i < declared.size(); ++i) {
        const std::string& name = declared.spec(static_cast<int>(i)).name;
        if (!recorded.count(name))
            std::printf("knob new in this build: %s (default %s)\n", name.c_str(), declared.format(static_cast<int>(i)).c_str());
    }
    const RecordFields build = ExperimentRecord::buildFields();
    for (const auto& [k, v] : build)
        for (const auto& [ok, ov] : old.build)
            if (k == ok && v != ov) std::printf("build %s: %s -> %s\n", k.c_str(), ov.c_str(), v.c_str());

    Scene loaded = loadScene(run.sceneSpec());
    auto context = HeadlessGlContext::create();
    RenderSession session;
    for (const auto& [k, v] : old.gl)
        if (k == "renderer" && v != session.glInfo().renderer)
            std::printf("gl renderer: %s -> %s\n", v.c_str(), session.glInfo().renderer.c_str());
    session.setScene(std::move(loaded), run);
    session.camera() = old.camera;
    session.resize(run.width, run.height);
    FrameRequest request;
    request.outputs = {old.buffer};
    PassTimer& timer = session.pipeline().timer();
    timer.setHistoryLength(std::max<size_t>(PassTimer::kHistory, static_cast<size_t>(run.warmup + run.frames)));
    std::uint64_t firstCounted = 0;
    for (int i = 0; i < run.warmup + run.frames; ++i) {
        const FrameReport report = session.render(request);
        if (i == run.warmup) firstCounted = report.frameIndex;
    }
    const ExperimentRecord now = ExperimentRecord::capture(session, run, old.buffer, firstCounted, context->platform());
    if (newRecord) now.write(*newRecord);

    // Timings: old against new, per series both have, with the interval of new / old.
    std::map<std::string, const RecordedSeries*> oldSeries;
    for (const auto& s : old.timings) oldSeries[s.name] = &s;
    for (const auto& s : now.timings) {
        const auto it = oldSeries.find(s.name);
        if (it == oldSeries.end()) continue;
        const RatioInterval r = bootstrapRatioOfMedians(s.gpuMs, it->second->gpuMs);
        std::printf("timing %-28s gpu median %9.3f -> %9.3f ms", s.name.c_str(), median(it->second->gpuMs), median(s.gpuMs));
        if (r.valid()) std::printf("  x%.3f [%.3f, %.3f]", r.ratio, r.low, r.high);
        std::printf("\n");
    }
    if (now.imageSha256 == old.imageSha256) {
        std::printf("image: identical\n");
        return 0;
    }
    std::printf("image: differs (sha256 %s -> %s)\n", old.imageSha256.c_str(), now.imageSha256.c_str());
    return 1;
}

}  // namespace dw
