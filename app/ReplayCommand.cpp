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
// error equal, no frame time moved beyond that band); 1: it differs; 2: the record is
// refused. docs/records.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <tuple>

#include "app/CommandLine.h"
#include "app/Commands.h"
#include "app/HeadlessGlContext.h"
#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/bench/Bootstrap.h"
#include "renderer/bench/TradeoffStudy.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/ShaderSource.h"
#include "renderer/record/BuildInfo.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/record/SceneFiles.h"
#include "renderer/record/ShaderFiles.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

std::string shortHash(const std::string& h) { return h.empty() ? "unreadable" : h.substr(0, 16); }

// A timing ratio (new / old) is reported as a change when its whole 95%
// interval lies outside this band: run-to-run noise on a shared machine stays inside.
constexpr double kTimingBandLow = 0.8, kTimingBandHigh = 1.25;

bool timingMoved(const RatioInterval& r) { return r.valid() && (r.low > kTimingBandHigh || r.high < kTimingBandLow); }

void printTooFew(size_t now, size_t old) {
    std::printf("  %s (%zu and %zu frames, %zu needed on each side)", kTooFewForInterval.c_str(), old, now,
                kMinIntervalSamples);
}

// Below this a median prints as 0.000 ms: the timer's noise, not a time to divide by.
constexpr double kZeroMs = 0.0005;

// Prints the ratio new / old of two series' GPU medians with its interval,
// or why there is none, and returns the interval (invalid when none: such a
// timing never counts as moved). An old median that prints as 0.000 ms has
// no ratio ("n/a (0 ms)"; 0/0 when both are); an old series whose resamples
// reach a 0 ms median has a ratio but no upper bound, so no interval.
// `markMoved`: say "(moved)" after an interval wholly outside the band
// (bench, where that decides; a render record's timings decide nothing).
RatioInterval printRatio(const std::vector<double>& now, const std::vector<double>& old, int resamples = 2000,
                         bool markMoved = false) {
    if (old.empty() || now.empty()) {
        std::printf("  n/a (no frames)");
        return {};
    }
    const double before = median(old), after = median(now);
    if (!(before >= kZeroMs)) {
        std::printf("  n/a (0 ms)");
        return {};
    }
    if (!enoughForInterval(now.size()) || !enoughForInterval(old.size())) {
        printTooFew(now.size(), old.size());
        return {};
    }
    const RatioInterval r = bootstrapRatioOfMedians(now, old, resamples);
    if (!r.valid() || r.resamples < resamples || !std::isfinite(r.low) || !std::isfinite(r.high)) {
        std::printf("  x%.3f, no interval (0 ms medians among the old frames' resamples)", after / before);
        return {};
    }
    std::printf("  x%.3f [%.3f, %.3f]%s", r.ratio, r.low, r.high, markMoved && timingMoved(r) ? " (moved)" : "");
    return r;
}

// "a, b, c and N more": at most `shown` names.
std::string someOf(const std::vector<std::string>& names, size_t shown = 3) {
    std::string out;
    for (size_t i = 0; i < names.size() && i < shown; ++i) out += (i ? ", " : "") + names[i];
    if (names.size() > shown) out += " and " + std::to_string(names.size() - shown) + " more";
    return out;
}

// The inputs replay finds changed (scene files, shader files, knobs the
// build lacks or adds, build fields, the GL renderer), each named, for the
// "inputs changed (N): ..." line. They never decide the exit code: the
// image (or bench's and tradeoff's rules) does.
struct ChangedInputs {
    std::vector<std::string> names;
    void add(const std::string& name) { names.push_back(name); }
    void print() const {
        if (names.empty()) {
            std::printf("inputs changed: none\n");
            return;
        }
        std::string all;
        for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
        std::printf("inputs changed (%zu): %s\n", names.size(), all.c_str());
    }
};

// Each changed, added or removed file (a scene's or a shader), named on a
// line of its own and counted as a changed input; `removedWhy` ends the
// removed file's line.
void reportFileChanges(const std::string& what, const std::vector<SceneFileChange>& changes,
                       const std::string& removedWhy, ChangedInputs& inputs) {
    for (const SceneFileChange& c : changes) {
        if (c.kind == SceneFileChange::Kind::Changed)
            std::printf("%s changed: %s (sha256 %s -> %s)\n", what.c_str(), c.path.c_str(),
                        shortHash(c.oldSha256).c_str(), shortHash(c.newSha256).c_str());
        else if (c.kind == SceneFileChange::Kind::Added)
            std::printf("%s added: %s (sha256 %s; the record does not list it)\n", what.c_str(), c.path.c_str(),
                        shortHash(c.newSha256).c_str());
        else
            std::printf("%s removed: %s (recorded sha256 %s; %s)\n", what.c_str(), c.path.c_str(),
                        shortHash(c.oldSha256).c_str(), removedWhy.c_str());
        inputs.add(what + " " + c.path);
    }
}

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
    FrameRequest request;
    request.outputs = {old.buffer};
    PassTimer& timer = session.pipeline().timer();
    timer.setHistoryLength(std::max<size_t>(PassTimer::kHistory, static_cast<size_t>(run.warmup + run.frames)));
    std::uint64_t firstCounted = 0;
    for (int i = 0; i < run.warmup + run.frames; ++i) {
        const FrameReport report = session.render(request);
        if (i == run.warmup) firstCounted = report.frameIndex;
    }
    ExperimentRecord now = ExperimentRecord::capture(session, run, old.buffer, firstCounted, context->platform());
    now.command = old.command;
    if (newRecord) now.write(*newRecord);

    // Timings: old against new, per series both have, with the interval of new / old.
    std::map<std::string, const RecordedSeries*> oldSeries;
    for (const auto& s : old.timings) oldSeries[s.name] = &s;
    for (const auto& s : now.timings) {
        const auto it = oldSeries.find(s.name);
        if (it == oldSeries.end()) continue;
        std::printf("timing %-28s gpu median %9.3f -> %9.3f ms", s.name.c_str(), median(it->second->gpuMs), median(s.gpuMs));
        printRatio(s.gpuMs, it->second->gpuMs);
        std::printf("\n");
    }
    reportShaders(old, now.shaders, inputs);
    inputs.print();
    if (now.imageSha256 == old.imageSha256) {
        std::printf("image: identical\n");
        return 0;
    }
    std::printf("image: differs (sha256 %s -> %s)\n", old.imageSha256.c_str(), now.imageSha256.c_str());
    return 1;
}

std::string fieldOrEmpty(const BenchFields& fields, const std::string& key) {
    for (const auto& [k, v] : fields)
        if (k == key) return v;
    return "";
}

// One configuration of a bench record's results: its axes, lights per pixel
// and the ratio series' GPU ms per counted frame.
struct RecordedConfig {
    std::string label;
    double lpp = NAN;
    std::vector<double> gpuMs;
};

std::string configLabel(const BenchConfig& c, const std::vector<std::string>& axes) {
    std::string label = c.size() + ", " + std::to_string(c.lights) + " lights";
    for (size_t k = 0; k < axes.size() && k < c.knobValues.size(); ++k) label += ", " + axes[k] + "=" + c.knobValues[k];
    return label;
}

int replayBench(const ExperimentRecord& old, const std::vector<std::string>& sets, const std::optional<std::string>& newRecord,
                ChangedInputs& inputs) {
    const RecordedBench& recorded = *old.bench;
    const std::string series = recorded.ratioOf;
    std::map<int, RecordedConfig> before;
    const nlohmann::ordered_json& res = old.benchResults;
    if (res.contains("configs") && res["configs"].is_array())
        for (const auto& c : res["configs"]) {
            if (!c.is_object() || !c.contains("config") || !c["config"].is_number_integer()) continue;
            RecordedConfig& r = before[c["config"].get<int>()];
            if (c.contains("lpp") && c["lpp"].is_number()) r.lpp = c["lpp"].get<double>();
            if (c.contains("samples") && c["samples"].is_array())
                for (const auto& s : c["samples"])
                    if (s.is_object() && s.contains("gpu_ms") && s["gpu_ms"].is_object() && s["gpu_ms"].contains(series) &&
                        s["gpu_ms"][series].is_number())
                        r.gpuMs.push_back(s["gpu_ms"][series].get<double>());
        }

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

    int lppDiffer = 0, moved = 0;
    std::vector<std::string> notInRecord, notRunAgain;
    std::map<int, std::vector<double>> afterMs;
    for (const auto& s : results.samples)
        if (s.series == series) afterMs[s.config].push_back(s.gpuMs);
    for (const auto& c : results.configs) {
        const int i = c.config.index;
        const std::string label = configLabel(c.config, results.knobAxes);
        const auto it = before.find(i);
        if (it == before.end()) {
            std::printf("config %d (%s): not in the record\n", i, label.c_str());
            notInRecord.push_back("config " + std::to_string(i) + " (" + label + ")");
            continue;
        }
        const RecordedConfig& b = it->second;
        const std::vector<double>& a = afterMs[i];
        std::printf("config %d (%s): %s gpu median %9.3f -> %9.3f ms", i, label.c_str(), series.c_str(), median(b.gpuMs),
                    median(a));
        const RatioInterval r = printRatio(a, b.gpuMs, recorded.resamples, true);
        const bool bothLpp = std::isfinite(b.lpp) && std::isfinite(c.lpp);
        // The JSON holds LPP rounded to 6 significant digits.
        const bool sameLpp = (!std::isfinite(b.lpp) && !std::isfinite(c.lpp)) ||
                             (bothLpp && std::abs(b.lpp - c.lpp) <= 1e-5 * std::max(1.0, std::abs(b.lpp)));
        if (bothLpp) std::printf("  lpp %.4f -> %.4f", b.lpp, c.lpp);
        std::printf("\n");
        if (!sameLpp) ++lppDiffer;
        if (timingMoved(r)) ++moved;
        before.erase(it);
    }
    for (const auto& [i, b] : before) {
        std::printf("config %d: in the record, not run again\n", i);
        notRunAgain.push_back("config " + std::to_string(i));
    }
    reportShaders(old, shaderFilesOf(results.shaders), inputs);
    inputs.print();
    const bool differs = !notInRecord.empty() || !notRunAgain.empty() || lppDiffer > 0 || moved > 0;
    if (!differs) {
        std::printf("bench: the same (%zu configurations, lights per pixel equal, no %s timing outside [%.2f, %.2f] "
                    "with its 95%% interval)\n",
                    results.configs.size(), series.c_str(), kTimingBandLow, kTimingBandHigh);
        return 0;
    }
    // A record cut short (its results lack configurations of the grid it declares) names them.
    std::string missing;
    if (!notInRecord.empty())
        missing += std::to_string(notInRecord.size()) + " configuration(s) not in the record: " + someOf(notInRecord) + "; ";
    if (!notRunAgain.empty())
        missing += std::to_string(notRunAgain.size()) + " in the record, not run again: " + someOf(notRunAgain) + "; ";
    std::printf("bench: differs (%s%d configuration(s) with other lights per pixel, %d with %s timing moved beyond "
                "[%.2f, %.2f])\n",
                missing.c_str(), lppDiffer, moved, series.c_str(), kTimingBandLow, kTimingBandHigh);
    return 1;
}


std::string pointLabel(const TradeoffTable& t, const TradeoffRow& r) {
    std::string label = "point " + std::to_string(r.point) + " camera " + r.camera;
    for (size_t a = 0; a < t.axes.size() && a < r.axisValues.size(); ++a) label += ", " + t.axes[a] + "=" + r.axisValues[a];
    return label;
}

// Errors are deterministic on one machine (the same frames, the same
// reference from the cache): equal to 1e-9 relative, or both not measured.
bool sameError(double a, double b) {
    if (!std::isfinite(a) || !std::isfinite(b)) return std::isfinite(a) == std::isfinite(b);
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
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
    TradeoffStudyProgress progress;
    progress.warning = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    const TradeoffMeasurement m = TradeoffStudy::measure(runner, again.aoRays, context->platform(), progress);
    for (const auto& [k, v] : old.gl)
        if (k == "renderer" && v != fieldOrEmpty(m.machine, "gl_renderer")) {
            std::printf("gl renderer: %s -> %s\n", v.c_str(), fieldOrEmpty(m.machine, "gl_renderer").c_str());
            inputs.add("gl renderer");
        }
    const TradeoffTable& after = m.result.table;
    if (newRecord)
        ExperimentRecord::forTradeoff(again, runner.scene(), m.result, m.machine).write(*newRecord);

    std::map<std::tuple<int, std::string, std::string, std::string>, const TradeoffRow*> recorded;
    for (const auto& r : before.rows) recorded[{r.point, r.camera, r.metric, r.buffer}] = &r;
    int errorDiffer = 0, moved = 0, missing = 0;
    for (const auto& r : after.rows) {
        const auto it = recorded.find({r.point, r.camera, r.metric, r.buffer});
        if (it == recorded.end()) {
            std::printf("%s: not in the record\n", pointLabel(after, r).c_str());
            ++missing;
            continue;
        }
        const TradeoffRow& b = *it->second;
        const bool same = sameError(b.error, r.error);
        // The difference of the medians, with the interval the two 95%
        // intervals allow (new low - old high, new high - old low).
        const double diff = r.frameGpuMs - b.frameGpuMs, lo = r.frameGpuMsLo - b.frameGpuMsHi,
                     hi = r.frameGpuMsHi - b.frameGpuMsLo;
        const double ratioLo = b.frameGpuMsHi > 0 ? r.frameGpuMsLo / b.frameGpuMsHi : NAN;
        const double ratioHi = b.frameGpuMsLo > 0 ? r.frameGpuMsHi / b.frameGpuMsLo : NAN;
        // Rows of a record without "frames" counted the record's frames.
        const size_t framesBefore = static_cast<size_t>(b.frames > 0 ? b.frames : old.frames);
        const size_t framesAfter = static_cast<size_t>(r.frames > 0 ? r.frames : again.options.frames);
        const bool interval = enoughForInterval(framesBefore) && enoughForInterval(framesAfter);
        const bool timeMoved = interval && std::isfinite(ratioLo) && std::isfinite(ratioHi) &&
                               (ratioLo > kTimingBandHigh || ratioHi < kTimingBandLow);
        std::printf("%s: %s %.6g -> %.6g (%s); frame gpu median %.3f -> %.3f ms, difference %+.3f", pointLabel(after, r).c_str(),
                    r.metric.c_str(), b.error, r.error, same ? "same" : "differs", b.frameGpuMs, r.frameGpuMs, diff);
        if (interval) std::printf(" [%+.3f, %+.3f]%s", lo, hi, timeMoved ? " (moved)" : "");
        else printTooFew(framesAfter, framesBefore);
        std::printf("\n");
        if (!same) ++errorDiffer;
        if (timeMoved) ++moved;
        recorded.erase(it);
    }
    for (const auto& [key, b] : recorded) {
        std::printf("%s: in the record, not run again\n", pointLabel(before, *b).c_str());
        ++missing;
    }
    reportShaders(old, shaderFilesOf(m.result.shaders), inputs);
    inputs.print();
    if (errorDiffer == 0 && moved == 0 && missing == 0) {
        std::printf("tradeoff: the same (%zu rows, every error equal, no frame time outside [%.2f, %.2f] with its "
                    "95%% interval)\n",
                    after.rows.size(), kTimingBandLow, kTimingBandHigh);
        return 0;
    }
    std::printf("tradeoff: differs (%d row(s) with another error, %d with the frame time moved beyond [%.2f, %.2f], "
                "%d not in both)\n",
                errorDiffer, moved, kTimingBandLow, kTimingBandHigh, missing);
    return 1;
}
}  // namespace

int runReplayCommand(int argc, char** argv) {
    CommandLine cl(argc, argv, 2, "replay");
    if (cl.flag("--help")) {
        std::cout << "usage: deferred-workbench replay RECORD.json [--record FILE]\n"
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
                     "Then 'inputs changed (N): ...' names every changed input (scene file, shader file, knob the\n"
                     "build lacks or adds, build field, GL renderer), or 'inputs changed: none'.\n"
                     "Exit codes: the result decides, not the inputs. 0: the same (the image identical, even when\n"
                     "inputs changed; for bench every configuration there, its lights per pixel equal and no timing\n"
                     "ratio's interval wholly outside [0.8, 1.25]; for tradeoff every row there, its error equal, no\n"
                     "frame time moved beyond that band); 1: it differs (even when no input changed);\n"
                     "2: the record is refused. docs/records.md.\n";
        return 0;
    }
    const auto newRecord = cl.value("--record");
    cl.finish("replay");
    if (cl.positional().size() != 1) throw UsageError("replay needs one record file: deferred-workbench replay RECORD.json");
    const std::string path = cl.positional()[0];

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

    // What cannot be restored (a scene that does not load, a knob value the
    // registry refuses, a configuration this build's checks refuse) refuses
    // the record too.
    try {
        // The scene as it loads now; the files it reads against the record's,
        // by name. Only the loader's files are read: a path the record alone
        // names is reported, never opened.
        Scene loaded = loadScene(old.sceneSpec);
        ChangedInputs inputs;
        reportFileChanges("scene file",
                          compareSceneFiles(old.sceneFiles, old.sceneSpec, sceneFilesOf(loaded), loaded.source),
                          "the scene no longer reads it", inputs);
        const std::vector<std::string> sets = restoredKnobs(old, inputs);
        for (const auto& [k, v] : buildFields())
            for (const auto& [ok, ov] : old.build)
                if (k == ok && v != ov) {
                    std::printf("build %s: %s -> %s\n", k.c_str(), ov.c_str(), v.c_str());
                    inputs.add("build " + k);
                }
        if (old.command == "bench") return replayBench(old, sets, newRecord, inputs);
        if (old.command == "tradeoff") return replayTradeoff(old, path, sets, newRecord, inputs);
        return replayRender(old, std::move(loaded), sets, newRecord, inputs);
    } catch (const GlUnsupportedError&) {
        throw;
    } catch (const Error& e) {
        // A shader that no longer compiles: which shader files changed since
        // the record (those it names, looked up in the folder used now).
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
        return 2;
    }
}

}  // namespace dw
