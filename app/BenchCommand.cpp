// deferred-workbench bench: lighting strategies (or any knob) side by side,
// against light count and render size, in one process; `bench merge` joins
// the CSVs of shards. docs/bench.md says how to run it and what each column means.
#include <fcntl.h>
#include <malloc.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "app/HostInfo.h"
#include "app/SweepOptions.h"
#include "renderer/OptionLimits.h"
#include "app/Commands.h"
#include "headless/CommandLine.h"
#include "headless/HeadlessGlContext.h"
#include "headless/PlotScript.h"
#include "renderer/Error.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/bench/BenchMerge.h"
#include "renderer/bench/BenchRunner.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/record/ExperimentRecord.h"

namespace dw {

namespace fs = std::filesystem;

namespace {

// What bench's shared options (SweepOptions) mean here.
const SweepCommand kBench = [] {
    SweepCommand c;
    c.name = "bench";
    c.frames = 10;
    c.plotSize = "800x500";
    c.plotByDefault = false;
    c.sweepWhat = "a knob axis, e.g. lighting.strategy=stencil_volumes,volumes,fullscreen";
    c.camerasWhat = "the table averages over them (medians over all frames)";
    c.shardWhat =
        "run the i-th of n slices of the grid: the configurations compared with each\n"
        "               other (differing only in the baseline's axis) form a group, and shard i runs\n"
        "               the groups whose number % n == i; bench merge takes --baseline and --ratio-of\n"
        "               from the shards' JSONs unless it is given its own";
    c.filesWhat = "the samples (every counted frame, every pass), and an experiment record whose results are\n"
                  "               the summary with the machine (deferred-workbench replay runs it again)";
    c.plotWhat = "frame ms against light count per configuration, log-log, drawn by\n"
                 "               scripts/bench_plot.py (python3-matplotlib); only with --plot";
    return c;
}();

std::string benchUsage() {
    return "usage: deferred-workbench bench [--scene NAME|FILE] [--preset NAME|FILE] [--set knob=value]...\n"
           "                                [--size WxH[,WxH...]] [--lights N[,N...]] [--light-radius R] [--seed N]\n"
           "                                [--keep-scene-lights] [--sweep knob=v1,v2,...]... [--exclude axis=v,...]...\n"
           "                                [--frames N] [--warmup N] [--block K] [--orbit N | --walkthrough]\n"
           "                                [--lpp-poses N] [--no-lpp] [--no-counters] [--baseline axis=value] [--ratio-of SERIES]\n"
           "                                [--resamples N] [--shard i/n] [--csv FILE] [--record FILE] [--plot FILE.png]\n"
           "                                [--plot-size WxH] [--resume PARTIAL.csv] [--quiet]\n"
           "       deferred-workbench bench merge SHARD.csv... --out ALL.csv [--record FILE] [--plot FILE.png]\n"
           "                                [--plot-size WxH] [--baseline axis=value] [--ratio-of SERIES] [--resamples N]\n"
           "  --animation  which glTF animation clip plays: a clip's name or index (0-based over the scene's\n"
           "               clips), or none; default each file's first (docs/scene-format.md, \"Animation\")\n"
           "  --size       render sizes (default 640x360); one session per size, all in one process\n"
           "  --lights     point-light counts, generated from --seed (default 1) into the scene's bounds,\n"
           "               replacing the scene's lights (--keep-scene-lights adds them); without it the\n"
           "               scene's own lights\n"
           "  --light-radius  each generated light's volume radius at lighting.threshold (default: a tenth\n"
           "               of the scene bounds' diagonal)\n"
           "  --lpp-poses  poses the untimed lights-per-pixel frame averages on a moving camera (default 4)\n"
           "  --baseline   the configuration each ratio divides by, as axis=value (size, lights or a swept\n"
           "               knob); default: the first value of the first swept knob (else lights, else size)\n"
           "  --ratio-of   the series each ratio and its interval compare: frame (the default), a pass\n"
           "               (e.g. lighting: the strategies alone) or a span PASS/NAME; list passes names\n"
           "               the passes; a series no configuration recorded is an error after the run\n"
           "  --resume     the CSV of an interrupted run of the same grid (samples are written as they are\n"
           "               measured): its counted frames are kept, the rest measured\n" +
           SweepOptions::help(kBench) + SweepMergeOptions::help(kBench) + CommandLine::rangesHelp("bench") +
           CommandLine::rangesHelp("bench merge");
}

// What the run ran on, besides the GL strings the runner reads.
BenchFields hostFields() {
    BenchFields f;
    f.emplace_back("cpu", cpuModel());
    f.emplace_back("cpu_threads", std::to_string(std::thread::hardware_concurrency()));
    char host[256] = {};
    if (gethostname(host, sizeof(host) - 1) == 0) f.emplace_back("host", host);
    utsname u{};
    if (uname(&u) == 0) f.emplace_back("os", std::string(u.sysname) + " " + u.release + " " + u.machine);
    f.emplace_back("compiler", compilerName());
#ifdef DW_BUILD_TYPE
    f.emplace_back("build_type", DW_BUILD_TYPE);
#endif
#ifdef DW_GIT_COMMIT
    f.emplace_back("git_commit_at_configure", DW_GIT_COMMIT);
#endif
    f.emplace_back("date", utcNow());
    return f;
}

// Draws the plot with scripts/bench_plot.py (PlotScript); false (after saying why) when it cannot.
bool drawPlot(const std::string& csv, const std::string& png, int width, int height) {
    return runPlotScript("bench_plot.py", "DW_BENCH_PLOT_SCRIPT",
                         {"--csv", csv, "--out", png, "--size", std::to_string(width) + "x" + std::to_string(height)},
                         "bench");
}

// The exit code: 1 when --plot was asked for and could not be drawn (the CSV and JSON are written).
int writePlot(const std::string& csv, const std::string& png, int width, int height) {
    if (!drawPlot(csv, png, width, height)) return 1;
    std::printf("wrote %s (%dx%d)\n", png.c_str(), width, height);
    return 0;
}

void printTables(const BenchResults& results, const BenchSummary& summary, const std::string& title, int resamples) {
    std::printf("## %s\n\n%s\n\n%s\n%s\n\n%s\n", title.c_str(), mainTableCaption(summary, resamples).c_str(),
                markdownTable(results, summary).c_str(), passTableCaption().c_str(),
                markdownPassTable(results, summary).c_str());
}

std::string fieldOr(const BenchFields& f, const std::string& key, const std::string& fallback) {
    for (const auto& [k, v] : f)
        if (k == key) return v;
    return fallback;
}


// Writes every file it is given even when one fails (a full disk for the
// CSV leaves the JSON written), then throws the first failure, the others
// said on stderr first.
void writeEach(const std::vector<std::function<void()>>& writes) {
    std::optional<FileError> first;
    for (const auto& write : writes) {
        try {
            write();
        } catch (const FileError& e) {
            if (first) std::fprintf(stderr, "deferred-workbench: error: %s\n", e.what());
            else first = e;
        }
    }
    if (first) throw *first;
}

// After the tables: the configurations that have a baseline but no ratio,
// because one of the two has no samples of the ratio's series (a pass that
// runs in some configurations only, such as dof with dof.enabled swept). No
// ratio at all is an error; some missing, a warning naming them.
void checkRatiosMade(const BenchSummary& summary, const std::string& series) {
    int compared = 0;
    std::string missing;
    for (const auto& r : summary.rows) {
        if (r.baseline < 0 || r.baseline == r.config) continue;
        ++compared;
        if (!r.ratio.valid()) missing += (missing.empty() ? "" : ", ") + std::to_string(r.config);
    }
    if (missing.empty()) return;
    const std::string why = "'" + series + "' is not in every configuration and its baseline";
    if (std::count(missing.begin(), missing.end(), ',') + 1 == compared)
        throw Error("--ratio-of: no configuration has a ratio: " + why + " (the tables and files are written)");
    std::fprintf(stderr, "bench: warning: no ratio for configuration(s) %s: %s\n", missing.c_str(), why.c_str());
}

// --ratio-of before a run: the frame, a pass of the pipeline or a span of
// one ("PASS/NAME", whose names are known only once the pass runs). Throws
// Error naming the passes. Whether the pass runs is known after the run.
void checkRatioSeriesNamesAPass(const std::string& series) {
    if (series == PassTimer::kFrameSeries) return;
    KnobRegistry knobs;
    const Pipeline pipeline(knobs);
    const std::string pass = series.substr(0, series.find('/'));
    std::string names;
    for (const PassInfo& p : pipeline.passList()) {
        if (p.name == pass && (pass == series || series.size() > pass.size() + 1)) return;
        names += (names.empty() ? "" : ", ") + p.name;
    }
    throw Error("--ratio-of: '" + series + "' is not frame, a pass (" + names + ") or a span PASS/NAME of one");
}

int runMerge(int argc, char** argv) {
    CommandLine cl(argc, argv, 3, "bench merge");
    if (cl.flag("--help")) {
        std::cout << benchUsage();
        return 0;
    }
    SweepMergeOptions m = SweepMergeOptions::read(cl, kBench);
    const std::optional<std::string> baselineGiven = cl.value("--baseline");
    const std::optional<std::string> ratioOfGiven = cl.value("--ratio-of");
    const int resamples = SweepOptions::readResamples(cl);
    cl.finish("bench merge");
    CommandLine::NamedFiles shardJsons;
    for (const auto& in : cl.positional())
        shardJsons.emplace_back("the shard's JSON", fs::path(in).replace_extension(".json").string());
    m.check(cl, kBench, shardJsons);
    const std::vector<std::string>& inputs = m.inputs;
    const std::string& out = *m.out;
    const std::optional<std::string>& json = m.json;
    const std::optional<std::string>& plot = m.plot;
    const int plotW = m.plotWidth, plotH = m.plotHeight;

    BenchMerged merged = mergeBenchShards(inputs, baselineGiven, ratioOfGiven,
                                          [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
    BenchResults& all = merged.results;
    const BenchBaseline& baseline = merged.baseline;
    const std::string& ratioOf = baseline.series;
    const BenchSummary summary = summarize(all, baseline, resamples);
    printTables(all, summary,
                "bench merge: " + std::to_string(all.configs.size()) + " configurations from " +
                    std::to_string(inputs.size()) + " shard(s)",
                resamples);
    std::fflush(stdout);
    std::vector<std::function<void()>> outputs = {[&] { all.writeCsv(out); }};
    if (json) outputs.push_back([&] { writeBenchJson(*json, all, summary); });
    writeEach(outputs);
    std::printf("wrote %s%s\n", out.c_str(), json ? (", " + *json).c_str() : "");
    const int plotted = plot ? writePlot(out, *plot, plotW, plotH) : 0;
    checkRatiosMade(summary, ratioOf);
    return plotted;
}

// Freed memory stays with the process for the whole run. By default glibc
// returns the top of the heap to the system and serves large blocks with
// mmap, so a configuration that followed a smaller one paid page faults
// for the memory the smaller one gave back: interleaving 1 and 1000
// lights doubled stencil_volumes' CPU time at 1000 lights (18 against
// 9 ms at 64x36) and added 12 ms to its lighting pass at 640x360.
void keepFreedMemory() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's most on 64-bit
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

// --seed, --light-radius, --keep-scene-lights, --lpp-poses, --no-lpp.
void readLightOptions(CommandLine& cl, BenchOptions& o) {
    o.seed = static_cast<std::uint32_t>(cl.whole("--seed", 1));
    const std::optional<double> lightRadius = cl.real("--light-radius");
    if (lightRadius) {
        o.lightRadius = static_cast<float>(*lightRadius);
        // Above 0 as a double, but below the smallest 32-bit float it is 0.
        if (!(o.lightRadius > 0.0f))
            throw UsageError("--light-radius must be at least the smallest 32-bit float (about 1.4e-45), got '" +
                             *cl.value("--light-radius") + "'");
    }
    // Options that change nothing without another one: said, not ignored.
    if (lightRadius && o.grid.lights.empty())
        std::fprintf(stderr, "bench: note: --light-radius sizes the generated lights; without --lights the scene's "
                             "own lights are used and it changes nothing\n");
    o.keepSceneLights = cl.flag("--keep-scene-lights");
    o.lppPoses = cl.whole("--lpp-poses", 4);
    o.lpp = !cl.flag("--no-lpp");
    o.counters = !cl.flag("--no-counters");
}

// The samples go to the CSV as they are measured, so a killed run keeps
// them (bench --resume continues from it); the whole file, in order, is
// written over it at the end. Streamed to a file only: a device or a pipe
// gets the whole file once, at the end.
class LiveCsv {
public:
    explicit LiveCsv(std::string path) : path_(std::move(path)) {
        std::error_code kind;
        failed_ = std::filesystem::exists(path_, kind) && !std::filesystem::is_regular_file(path_, kind);
    }
    BenchStream stream() {
        return [this](const BenchResults& soFar, const std::vector<BenchSample>& fresh) { write(soFar, fresh); };
    }
    void close() { out_.reset(); }

private:
    void write(const BenchResults& soFar, const std::vector<BenchSample>& fresh) {
        if (failed_) return;
        if (!out_) {
            out_ = std::make_unique<std::ofstream>(path_, std::ios::trunc);
            *out_ << BenchResults::csvHeader(soFar.knobAxes, soFar.counted) << "\n";
        }
        *out_ << soFar.csvRows(fresh);
        if (!out_->flush()) {
            failed_ = true;
            std::fprintf(stderr, "bench: warning: %s: cannot write the samples as they come; they are written at the end\n",
                         path_.c_str());
        }
    }
    std::string path_;
    std::unique_ptr<std::ofstream> out_;
    bool failed_ = false;
};

// The machine (GL platform, host) and the command line, in the run's fields.
void describeRun(BenchResults& results, const std::string& platform, BenchFields host, int argc, char** argv) {
    BenchFields machine = results.machine;
    machine.emplace_back("gl_platform", platform);
    for (auto& f : host) machine.push_back(std::move(f));
    results.machine = std::move(machine);
    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + shellQuoted(argv[i]);
    results.settings.emplace_back("command", command);
}

}  // namespace

namespace {
// Whether the counters of each configuration were the same in every counted frame (they are exact).
void sayCounters(const BenchResults& results) {
    if (!results.counted) return;
    const std::string mismatch = results.counterMismatch();
    if (mismatch.empty())
        std::printf("cost counters: the same in every counted frame of each configuration (the CSV's fragments .. "
                    "bytes columns)\n");
    else
        std::printf("cost counters: not the same in every counted frame: %s\n", mismatch.c_str());
}
}  // namespace

int runBenchCommand(int argc, char** argv) {
    if (argc > 2 && std::string(argv[2]) == "merge") return runMerge(argc, argv);
    CommandLine cl(argc, argv, 2, "bench");
    if (cl.flag("--help")) {
        std::cout << benchUsage();
        return 0;
    }
    BenchOptions o;
    o.run = cl.runConfig();
    o.run.sceneTime = cl.real("--scene-time").value_or(0.0);
    o.grid.sizes = SweepOptions::readSizes(cl, true);
    o.grid.lights = cl.wholeList("--lights");
    const SweepOptions so = SweepOptions::read(cl, kBench);
    o.grid.knobAxes = so.sweeps;
    o.exclude = so.exclusion;
    o.frames = so.frames;
    o.warmup = so.warmup;
    o.block = so.block;
    o.orbit = so.orbit;
    o.walkthrough = so.walkthrough;
    o.shard = so.shard;
    readLightOptions(cl, o);
    const bool keepSceneLights = o.keepSceneLights && !o.grid.lights.empty();
    const std::string shardText = so.shardText();
    const std::string& csv = so.csv;
    const std::string& json = so.json;
    const std::optional<std::string>& plot = so.plot;
    const int plotW = so.plotWidth, plotH = so.plotHeight;
    const std::string baselineSpec = cl.value("--baseline").value_or("");
    const std::string ratioOf = cl.value("--ratio-of").value_or(PassTimer::kFrameSeries);
    const int resamples = so.resamples;
    const bool quiet = so.quiet;
    const auto resumeFrom = cl.value("--resume");
    cl.finish("bench");
    if (!cl.positional().empty()) throw UsageError("bench: unexpected argument '" + cl.positional()[0] + "'");
    // The outputs are checked before the run, so a long run is never lost to a bad path.
    so.checkOutputs(kBench, CommandLine::inputFiles(o.run));
    checkRatioSeriesNamesAPass(ratioOf);
    if (o.orbit > 0 && o.frames % o.orbit != 0 && !quiet)
        std::fprintf(stderr, "bench: note: %d frames over %d orbit poses weigh the poses unequally\n", o.frames, o.orbit);

    keepFreedMemory();

    // Everything that can fail without GL fails here: knobs, values, the scene, the baseline.
    o.baseline = baselineSpec;
    const RecordedBench recorded{o, ratioOf, resamples};  // for the record (--json) the run writes
    BenchRunner runner(std::move(o));
    BenchBaseline baseline = runner.baseline();
    baseline.series = ratioOf;
    if (runner.configs().empty())
        std::fprintf(stderr, "bench: note: shard %s holds none of the grid's %zu configurations (more shards than "
                             "comparison groups); its files list none\n",
                     shardText.c_str(), runner.gridSize());
    for (const auto& w : runner.scene().warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

    // --resume: what an interrupted run of this grid measured (a last line cut short is left out).
    std::optional<BenchResults> resumed;
    if (resumeFrom) resumed = BenchResults::readCsv(*resumeFrom, true);

    // The samples go to the CSV as they are measured, so a killed run keeps
    // them (bench --resume continues from it); the whole file, in order, is
    // written over it at the end.
    LiveCsv live(csv);
    auto context = HeadlessGlContext::create();
    BenchResults results = runner.run(
        [&](const std::string& line) {
            if (!quiet) std::fprintf(stderr, "%s\n", line.c_str());
        },
        live.stream(), resumed ? &*resumed : nullptr);
    live.close();
    describeRun(results, context->platform(), hostFields(), argc, argv);

    const BenchSummary summary = summarize(results, baseline, resamples);
    // The tables first: should writing the files still fail, the run's figures are on stdout.
    printTables(results, summary,
                "bench: " + runner.scene().name + ", " + std::to_string(results.configs.size()) + " configuration(s) x " +
                    fieldOr(results.settings, "frames", "?") + " frame(s)" +
                    (results.configs.empty() ? std::string()
                                             : " on " + fieldOr(results.machine, "gl_renderer", "?")) +
                    (keepSceneLights ? "; the lights column: " + fieldOr(results.settings, "lights", "generated")
                                     : std::string()),
                resamples);
    sayCounters(results);
    std::fflush(stdout);
    writeEach({[&] { results.writeCsv(csv); }, [&] {
                  writeBenchFile(json, ExperimentRecord::forBench(recorded, runner.scene(), results, summary).json(json),
                                 "bench JSON");
              }});
    std::printf("wrote %s, %s\n", csv.c_str(), json.c_str());
    const int plotted = plot ? writePlot(csv, *plot, plotW, plotH) : 0;
    // A pass can be known and still not run (switched off, culled, a span
    // it never opened): the run's figures are written, then the ratio that
    // was asked for and could not be made is an error.
    if (!results.configs.empty() && !hasSeries(results, ratioOf))
        throw Error("--ratio-of: no configuration recorded '" + ratioOf +
                    "' (the pass did not run, or has no such span); the ratios are empty");
    checkRatiosMade(summary, ratioOf);
    return plotted;
}

}  // namespace dw
