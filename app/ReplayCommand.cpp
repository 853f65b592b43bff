// deferred-workbench replay RECORD.json: restores the state an experiment
// record holds and measures again, and says what changed: each scene file,
// shader file (compiled from the folder this build finds: $DW_SHADER_DIR
// first), knob and build field by name, then "inputs changed (N): ..." (or
// "inputs changed: none"), and
//   render / gui records: the image (sha256 of its pixels) and each timing
//     series old against new with the bootstrap interval of the ratio of medians;
//   tradeoff records: the same sweep run again, per point and camera the
//     error old against new (deterministic: any change is "differs") and the
//     frame's GPU median old against new with the interval of the difference;
//   bench records: the same grid (sizes, lights, sweep, frames, warm-up,
//     seed, camera path) run again, per configuration its lights per pixel
//     and the ratio series' GPU median old against new with the interval.
// The result decides the exit code, never the inputs: changed inputs with an
// identical image exit 0. Exit 0: the same (render: the image is identical; bench: every
// configuration is there, its lights per pixel equal, and no ratio's 95%
// interval lies wholly outside [0.8, 1.25]; tradeoff: every row there, its
// error, its interval and every counter (measured on both sides) equal, no
// frame, --time or term time moved beyond that band, no recorded median
// outside its own interval, the pick the same); 1: it differs; 2: the record is
// refused. docs/records.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <tuple>

#include "app/Commands.h"
#include "app/ReplayDiff.h"
#include "app/ReplayReport.h"
#include "app/ReplaySearch.h"
#include "headless/CommandLine.h"
#include "headless/HeadlessGlContext.h"
#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/study/TradeoffStudy.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/ShaderSource.h"
#include "renderer/record/BuildInfo.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/record/SceneFiles.h"
#include "renderer/record/ShaderFiles.h"
#include "renderer/reference/ViewReference.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

using replay::ChangedInputs;
using replay::reportFileChanges;

// The record's shader files against those the replay compiled (`now`).
void reportShaders(const ExperimentRecord& old, const RecordedShaders& now, ChangedInputs& inputs) {
    if (!old.shaders.present) {
        std::printf("record holds no shader hashes (written before records kept them)\n");
        return;
    }
    reportFileChanges("shader file", compareShaderFiles(old.shaders, now), "not in " + now.folder, inputs);
}

// The recorded knobs this build takes, as --set assignments; the others are
// named. A value the registry refuses (as --set would) refuses the record:
// throws Error naming each such knob (knobs.NAME: the registry's message).
std::vector<std::string> restoredKnobs(const ExperimentRecord& old, ChangedInputs& inputs) {
    const KnobRegistry declared = RunConfig::declaredKnobs();
    std::vector<std::string> sets, refused;
    std::map<std::string, std::string> recorded;
    for (const auto& [recordedName, value] : old.knobs) {
        // An old name (KnobAlias: ssao.enabled) restores the knob it became.
        const std::string name = declared.canonicalName(recordedName);
        if (name != recordedName) std::printf("knob renamed: %s -> %s (recorded %s)\n", recordedName.c_str(), name.c_str(), value.c_str());
        recorded[name] = value;
        if (!declared.find(name)) {
            std::printf("knob not in this build: %s (recorded %s)\n", name.c_str(), value.c_str());
            inputs.add("knob " + name);
            continue;
        }
        KnobRegistry probe = declared;
        try {
            probe.setFromString(name, value);
        } catch (const Error& e) {
            refused.push_back("knobs." + recordedName + ": " + e.what());
            continue;
        }
        sets.push_back(name + "=" + value);
    }
    for (size_t i = 0; i < declared.size(); ++i) {
        const std::string& name = declared.spec(static_cast<int>(i)).name;
        if (!recorded.count(name)) {
            std::printf("knob new in this build: %s (default %s)\n", name.c_str(), declared.format(static_cast<int>(i)).c_str());
            inputs.add("knob " + name);
        }
    }
    if (!refused.empty()) {
        std::string all;
        for (const auto& r : refused) all += (all.empty() ? "" : "; ") + r;
        throw Error(all);
    }
    return sets;
}

int replayRender(const ExperimentRecord& old, Scene loaded, const std::vector<std::string>& sets,
                 const std::optional<std::string>& newRecord, ChangedInputs& inputs) {
    RunConfig run;
    run.scene = old.sceneSpec;
    run.sets = sets;
    run.width = old.width;
    run.height = old.height;
    run.frames = old.frames;
    run.warmup = old.warmup;
    run.sceneTime = old.sceneTime;
    run.animation = old.animation;
    auto context = HeadlessGlContext::create();
    RenderSession session;
    for (const auto& [k, v] : old.gl)
        if (k == "renderer" && v != session.glInfo().renderer) {
            std::printf("gl renderer: %s -> %s\n", v.c_str(), session.glInfo().renderer.c_str());
            inputs.add("gl renderer");
        }
    session.setScene(std::move(loaded), run);
    session.camera() = old.camera;
    session.resize(run.width, run.height);
    // A reference buffer: the same trace (rays, seed) of the view as the last frame has it, as render does.
    std::optional<reference::ViewReference> traced;
    if (old.referenceAoRays) {
        reference::ViewReferenceOptions o;
        o.aoRays = *old.referenceAoRays;
        o.seed = static_cast<int>(old.referenceSeed);
        o.pixelSamples = old.referenceSpp;
        o.pixelFilter = reference::pixelFilterNamed(old.referenceFilter);
        o.cacheWarning = [](const std::string& why) { std::fprintf(stderr, "warning: the reference is not cached: %s\n", why.c_str()); };
        const std::uint64_t lastFrame = session.pipeline().frameIndex() + static_cast<std::uint64_t>(run.warmup + run.frames - 1);
        traced = reference::traceViewReference(session.scene(), session.knobs(), session.camera(), run.width,
                                                        run.height, o, lastFrame);
        session.showReference(&traced->images);
    }
    FrameRequest request;
    request.outputs = {old.buffer};
    PassTimer& timer = session.pipeline().timer();
    timer.setHistoryLength(std::max<size_t>(PassTimer::kHistory, static_cast<size_t>(run.warmup + run.frames)));
    // A record with cost counters is counted again, to compare them exactly.
    if (std::any_of(old.timings.begin(), old.timings.end(), [](const RecordedSeries& s) { return s.counts.measured(); }))
        timer.setCounting(true);
    std::uint64_t firstCounted = 0;
    FrameReport report;
    for (int i = 0; i < run.warmup + run.frames; ++i) {
        report = session.render(request);
        if (i == run.warmup) firstCounted = report.frameIndex;
    }
    // What a pass lost in the last frame (the oit pass's fragments), as render says it.
    for (const std::string& w : report.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
    ExperimentRecord now = ExperimentRecord::capture(session, run, old.buffer, firstCounted, context->platform());
    now.command = old.command;
    if (old.referenceAoRays) now.setReference(*old.referenceAoRays, old.referenceSeed, old.referenceSpp, old.referenceFilter);
    if (newRecord) now.write(*newRecord);

    // Timings: old against new, per series both have, with the interval of new / old.
    replay::compareTimings(old.timings, now.timings);
    const int counters = replay::compareCounters(old.timings, now.timings);
    reportShaders(old, now.shaders, inputs);
    inputs.print();
    return std::max(replay::imageVerdict(old.imageSha256, now.imageSha256), counters);
}

std::string fieldOrEmpty(const BenchFields& fields, const std::string& key) {
    for (const auto& [k, v] : fields)
        if (k == key) return v;
    return "";
}

std::string configLabel(const BenchConfig& c, const std::vector<std::string>& axes) {
    std::string label = c.size() + ", " + std::to_string(c.lights) + " lights";
    for (size_t k = 0; k < axes.size() && k < c.knobValues.size(); ++k) label += ", " + axes[k] + "=" + c.knobValues[k];
    return label;
}

int replayBench(const ExperimentRecord& old, const std::vector<std::string>& sets, const std::optional<std::string>& newRecord,
                ChangedInputs& inputs) {
    const RecordedBench& recorded = *old.bench;
    const std::string series = recorded.ratioOf;
    const std::map<int, replay::RecordedConfig> before = replay::recordedConfigs(old.benchResults, series);

    RecordedBench again = recorded;
    again.options.run.sets = sets;
    BenchRunner runner(again.options);
    auto context = HeadlessGlContext::create();
    BenchResults results = runner.run();
    results.machine.emplace_back("gl_platform", context->platform());
    for (const auto& [k, v] : old.gl)
        if (k == "renderer" && v != fieldOrEmpty(results.machine, "gl_renderer")) {
            std::printf("gl renderer: %s -> %s\n", v.c_str(), fieldOrEmpty(results.machine, "gl_renderer").c_str());
            inputs.add("gl renderer");
        }
    BenchBaseline baseline = runner.baseline();
    baseline.series = series;
    const BenchSummary summary = summarize(results, baseline, recorded.resamples);
    if (newRecord) ExperimentRecord::forBench(again, runner.scene(), results, summary).write(*newRecord);

    std::map<int, std::vector<double>> afterMs;
    for (const auto& sample : results.samples)
        if (sample.series == series) afterMs[sample.config].push_back(sample.gpuMs);
    std::vector<std::pair<int, replay::RecordedConfig>> after;
    for (const auto& c : results.configs)
        after.push_back({c.config.index, {configLabel(c.config, results.knobAxes), c.lpp, afterMs[c.config.index],
                                          gpuMemPeakMib(results.samples, c.config.index)}});
    const replay::BenchComparison compared = replay::compareBench(before, after, series, recorded.resamples);
    reportShaders(old, shaderFilesOf(results.shaders), inputs);
    inputs.print();
    return compared.verdict();
}

int replayTradeoff(const ExperimentRecord& old, const std::string& path, const std::vector<std::string>& sets,
                   const std::optional<std::string>& newRecord, ChangedInputs& inputs) {
    RecordedTradeoff again = *old.tradeoff;
    bool presetAxis = false;
    for (const auto& a : again.options.sweep.axes) presetAxis = presetAxis || a.name == "preset";
    if (presetAxis) {
        // Every knob as --set would hide each point's preset: the run's own preset and --set.
        again.options.run.setPreset("");
        for (const auto& p : again.runPresets) again.options.run.addPreset(p);
        again.options.run.sets = again.runSets;
    } else {
        again.options.run.sets = sets;
    }
    const TradeoffTable before = old.tradeoffTable(path);
    TradeoffRunner runner(again.options);
    auto context = HeadlessGlContext::create();
    if (again.search) {  // walked again from the same start (app/ReplaySearch.cpp)
        bool moved = false;
        const BudgetSearchResult found = replay::replaySearch(
            old, path, again, newRecord, {{"gl_platform", context->platform()}}, moved);
        reportShaders(old, shaderFilesOf(found.last.shaders), inputs);
        inputs.print();
        return moved ? 1 : 0;
    }
    TradeoffStudyProgress progress;
    progress.warning = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    const TradeoffMeasurement m = TradeoffStudy::measure(runner, again.aoRays, context->platform(), progress, again.referenceSeed,
                                                         {again.refSpp, reference::pixelFilterNamed(again.refFilter)});
    for (const auto& [k, v] : old.gl)
        if (k == "renderer" && v != fieldOrEmpty(m.machine, "gl_renderer")) {
            std::printf("gl renderer: %s -> %s\n", v.c_str(), fieldOrEmpty(m.machine, "gl_renderer").c_str());
            inputs.add("gl renderer");
        }
    const TradeoffTable& after = m.result.table;
    if (newRecord)
        ExperimentRecord::forTradeoff(again, runner.scene(), m.result, m.machine).write(*newRecord);

    replay::TradeoffComparison compared =
        replay::compareTradeoff(before, after, old.frames, again.options.frames, again.options.cost != "gpu_ms");
    compared.pickMoved = replay::reportPick(before, after);
    reportShaders(old, shaderFilesOf(m.result.shaders), inputs);
    inputs.print();
    return compared.verdict();
}
// The scene as it loads now: the files it reads (a built-in's content)
// against the record's, by name. Only the loader's files are read: a path the
// record alone names is reported, never opened.
void reportSceneFiles(const ExperimentRecord& old, const Scene& loaded, ChangedInputs& inputs) {
    std::vector<SceneFileChange> changes =
        compareSceneFiles(old.sceneFiles, old.sceneSpec, sceneFilesOf(loaded), loaded.source);
    // A record of a built-in scene written before built-ins were hashed has no entry for its content.
    const bool recordedContent = std::any_of(old.sceneFiles.begin(), old.sceneFiles.end(),
                                             [](const RecordedFile& f) { return isBuiltinSceneContent(f.path); });
    if (!recordedContent && isBuiltinSceneContent(loaded.source)) {
        std::erase_if(changes, [](const SceneFileChange& c) {
            return c.kind == SceneFileChange::Kind::Added && isBuiltinSceneContent(c.path);
        });
        std::printf("record holds no content hash of the built-in scene (written before records kept one)\n");
    }
    reportFileChanges("scene file", changes, "the scene no longer reads it", inputs);
}

// Each build field that differs from the record's ("build commit: OLD -> NEW").
void reportBuild(const ExperimentRecord& old, ChangedInputs& inputs) {
    for (const auto& [k, v] : buildFields())
        for (const auto& [ok, ov] : old.build)
            if (k == ok && v != ov) {
                std::printf("build %s: %s -> %s\n", k.c_str(), ov.c_str(), v.c_str());
                inputs.add("build " + k);
            }
}

// A record whose state cannot be restored: the reason on stderr; for a
// shader that no longer compiles, first the shader files changed since the
// record (those it names, looked up in the folder used now).
void refuseUnrestorable(const ExperimentRecord& old, const std::string& path, const Error& e) {
    if (dynamic_cast<const gl::ShaderError*>(&e) && old.shaders.present) {
        RecordedShaders now;
        try {
            now.folder = gl::ShaderLibrary::locateRoot().string();
        } catch (const Error&) {
        }
        ChangedInputs unused;
        reportShaders(old, now, unused);
    }
    std::fflush(stdout);
    std::fprintf(stderr, "refused: %s: cannot restore it: %s\n", path.c_str(), e.what());
}

}  // namespace

int runReplayCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2, "replay");
    if (cl.flag("--help")) {
        std::cout << "usage: deferred-workbench replay RECORD.json [--record FILE]\n"
                     "       deferred-workbench replay --diff A.json B.json\n"
                     "Restores the state of an experiment record (render, bench and tradeoff --record, the window's\n"
                     "record), measures again and names each changed scene file, shader file, knob and build field.\n"
                     "  render/window records: prints 'image: identical' or 'image: differs (sha256 old -> new)'\n"
                     "               and old against new timings with the 95% interval of each ratio\n"
                     "  bench records: runs the same grid again and prints, per configuration, the ratio series'\n"
                     "               GPU median old -> new with the interval of the ratio, and lights per pixel\n"
                     "  tradeoff records: runs the same sweep again and prints, per point and camera, the error\n"
                     "               old -> new (any change differs) and the frame time old -> new with the interval\n"
                     "               of the difference\n"
                     "  --record     write the new run's record too\n"
                     "Scene paths in the record are relative to its folder; the scene's files as it loads now are\n"
                     "compared with the record's (changed, added, removed by name). Shaders are compiled from the\n"
                     "folder this build finds ($DW_SHADER_DIR, else the source tree's shaders/, else one beside the\n"
                     "binary); every shader file the run compiled is compared with the record's by its path in that\n"
                     "folder (shader file changed/added/removed). Fields are held to the ranges of\n"
                     "the options they stand for, the camera to scene/CameraCheck, knob values to the registry.\n"
                     "Intervals need 6 frames a side; fewer print 'too few frames for an interval'.\n"
                     "A built-in scene is compared by the sha256 of its content (scene file changed: builtin:NAME).\n"
                     "A record edited since it was written (its fields against the record_sha256 written with them)\n"
                     "says 'record edited: its inputs ...' or '... its results ...' first.\n"
                     "Then 'inputs changed (N): ...' names every changed input (record inputs/results edited, scene\n"
                     "file, shader file, knob the build lacks or adds, build field, GL renderer), or 'inputs changed: none'.\n"
                     "  --diff A B   measures nothing: prints the inputs, knobs, build and results that differ\n"
                     "               between two records in the same words, then the verdict of B's results against\n"
                     "               A's (exit 0 the same, 1 they differ, 2 a record is refused)\n"
                     "Exit codes: the result decides, not the inputs. 0: the same (the image identical, even when\n"
                     "inputs changed; for bench every configuration there, its lights per pixel equal and no timing\n"
                     "ratio's interval wholly outside [0.8, 1.25]; for tradeoff every row there, its error, error\n"
                     "interval and counters equal (a counter one side lacks is not), no frame, --time or term time\n"
                     "moved beyond that band, no recorded median outside its interval, the pick the same; a --search\n"
                     "record: the same settings found and every evaluation both walks measured the same);\n"
                     "1: it differs (even when no input changed);\n"
                     "2: the record is refused. docs/records.md.\n";
        return 0;
    }
    const bool diff = cl.flag("--diff");
    const auto newRecord = cl.value("--record");
    cl.finish("replay");
    if (diff) {
        if (newRecord) throw UsageError("replay --diff compares two records and measures nothing: it takes no --record");
        if (cl.positional().size() != 2)
            throw UsageError("replay --diff needs two record files: deferred-workbench replay --diff A.json B.json");
        // In the order given (CommandLine hands back the word a bare flag took last).
        std::vector<std::string> files;
        for (int i = 2; i < argc; ++i)
            if (std::string(argv[i]) != "--diff") files.push_back(argv[i]);
        return runReplayDiff(files.at(0), files.at(1));
    }
    if (cl.positional().size() != 1) throw UsageError("replay needs one record file: deferred-workbench replay RECORD.json");
    const std::string path = cl.positional()[0];
    if (newRecord) {
        // The record replayed is the baseline: a --record over it would lose it.
        std::error_code ec;
        if (std::filesystem::equivalent(path, *newRecord, ec))
            throw UsageError("replay --record " + *newRecord + ": that is the record being replayed (" + path +
                             "); name another file, so the baseline is kept");
    }

    ExperimentRecord old;
    try {
        old = ExperimentRecord::read(path);
        if (old.bench && old.bench->merged)
            throw FileError(path, "a bench merge record has no grid to run again; replay each shard's record");
        if (old.tradeoff && old.tradeoff->merged)
            throw FileError(path, "a tradeoff merge record has no sweep to run again; replay each shard's record");
    } catch (const Error& e) {
        std::fprintf(stderr, "refused: %s\n", e.what());
        return 2;
    }
    if (old.readVersion < ExperimentRecord::kVersion)
        std::printf("record version %d, read as version %d (it recorded no camera path, seeds or compiler flags)\n",
                    old.readVersion, ExperimentRecord::kVersion);
    ChangedInputs inputs;
    // An edited record is named before anything is measured: its results
    // then say nothing about the machine.
    replay::reportSelfCheck(old, "", inputs);

    // What cannot be restored (a scene that does not load, a knob value the
    // registry refuses, a configuration this build's checks refuse) refuses
    // the record too.
    try {
        Scene loaded = loadScene(old.sceneSpec);
        reportSceneFiles(old, loaded, inputs);
        const std::vector<std::string> sets = restoredKnobs(old, inputs);
        reportBuild(old, inputs);
        if (old.command == "bench") return replayBench(old, sets, newRecord, inputs);
        if (old.command == "tradeoff") return replayTradeoff(old, path, sets, newRecord, inputs);
        return replayRender(old, std::move(loaded), sets, newRecord, inputs);
    } catch (const GlUnsupportedError&) {
        throw;
    } catch (const Error& e) {
        refuseUnrestorable(old, path, e);
        return 2;
    }
}

}  // namespace dw
