// deferred-workbench tradeoff: what each setting costs in GPU milliseconds
// and in error against the CPU reference (or a named configuration), and
// which settings are on the Pareto front; `tradeoff merge` joins shards.
// docs/tradeoffs.md says how to run it and what each column means.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "app/CommandLine.h"
#include "app/Commands.h"
#include "app/HeadlessGlContext.h"
#include "app/HostInfo.h"
#include "app/PlotScript.h"
#include "app/TradeoffMeasurement.h"
#include "renderer/Error.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

const char* const kTradeoffUsage =
    "usage: deferred-workbench tradeoff [--scene S] [--preset P] [--set knob=value]... [--size WxH]\n"
    "                                   [--sweep axis=v1,v2,...]... [--presets A,B,...] [--knobs speed/quality]\n"
    "                                   [--exclude axis=v[,v...][,axis=v...]]... [--against reference|knob=v[,knob=v...]]\n"
    "                                   [--metric flip|rms|psnr|ssim] [--buffer final|lbuffer|ao|shadow] [--ao-rays N]\n"
    "                                   [--mask shadow_edges] [--time frame|PASS]\n"
    "                                   [--orbit N | --walkthrough] [--frames N] [--warmup N] [--block K] [--resamples N]\n"
    "                                   [--shard i/n] [--csv FILE] [--json FILE] [--plot FILE.png] [--plot-size WxH]\n"
    "                                   [--quiet]\n"
    "       deferred-workbench tradeoff merge SHARD.csv|SHARD.json... --out ALL.csv [--json FILE] [--plot FILE.png] [--plot-size WxH]\n"
    "                                   [--time frame|PASS]\n"
    "  --sweep      an axis: a knob (ssao.samples=8,16,32), camera.near=... or camera.far=...; repeatable;\n"
    "               the full grid of every --sweep and --presets\n"
    "  --presets    presets as an axis (the column 'preset'): each point's knobs are the preset's, under --set\n"
    "  --knobs speed/quality  every knob the registry marks as trading speed for quality, one at a time\n"
    "               about the current settings (docs/tradeoffs.md says which values)\n"
    "  --exclude    a corner left out: every named axis at one of its values; repeatable\n"
    "  --against    what the error is measured against: the CPU reference (default; from the reference\n"
    "               cache, each camera's rendered once) or the point with these knob values on top\n"
    "  --metric     the error (default flip); --buffer the image it is measured on (default final;\n"
    "               ao = the AO buffer the lighting pass reads (ao.filtered); shadow = lighting.shadow, the\n"
    "               shadow factor as the reference's shadow buffer defines it); --ao-rays the reference's AO\n"
    "               rays per pixel (default 64)\n"
    "  --mask shadow_edges  the error over the pixels within 2 px of an edge of the reference's shadow\n"
    "               buffer only; the buffer column reads <buffer>:shadow_edges\n"
    "  --time       what the front ranks by: frame (default, frame_gpu_ms) or a pass (its gpu_ms.<pass>),\n"
    "               since on llvmpipe the frame time drowns a small pass's\n"
    "  --orbit N    N cameras on a circle about the run's camera; --walkthrough: each keyframe of the\n"
    "               scene's camera.path. Several cameras add a row per point over all of them\n"
    "  --frames     counted frames per point and camera (default 5); --warmup after each switch (default 1);\n"
    "               --block K counted frames in a row (default 1); --resamples for the 95% intervals (2000)\n"
    "  --size       the render size (default 640x360)\n"
    "  --shard i/n  the points whose number % n == i; join the CSVs with tradeoff merge\n"
    "  --csv, --json, --plot  default tradeoff.csv, tradeoff.json, tradeoff.png (tradeoff-shard-I-of-N.*\n"
    "               with --shard); the JSON is an experiment record (deferred-workbench replay runs it again;\n"
    "               tradeoff merge reads shards' CSVs or records); the plot by scripts/tradeoff_plot.py\n"
    "               (python3-matplotlib)\n"
    "  --quiet      no progress lines on stderr\n";

std::string number(double v, const char* format) {
    if (!std::isfinite(v)) return std::isinf(v) ? (v > 0 ? "inf" : "-inf") : "-";
    char text[64];
    std::snprintf(text, sizeof(text), format, v);
    return text;
}

// The rows a summary shows: the all-cameras rows when there are any, else every row.
std::vector<const TradeoffRow*> shownRows(const TradeoffTable& t) {
    std::vector<const TradeoffRow*> all, rows;
    for (const auto& r : t.rows) {
        rows.push_back(&r);
        if (r.camera == TradeoffTable::kAllCameras) all.push_back(&r);
    }
    return all.empty() ? rows : all;
}

std::string markdown(const TradeoffTable& t, const std::string& time = "frame") {
    const std::vector<const TradeoffRow*> rows = shownRows(t);
    const bool several = !rows.empty() && rows.front()->camera == TradeoffTable::kAllCameras;
    std::set<std::string> cameras;
    for (const auto& r : t.rows) cameras.insert(r.camera);
    const bool cameraColumn = !several && cameras.size() > 1;
    std::string out;
    std::vector<std::string> header = {"point"};
    header.insert(header.end(), t.axes.begin(), t.axes.end());
    if (cameraColumn) header.emplace_back("camera");
    const std::string metric = t.rows.empty() ? "error" : t.rows.front().metric + " (" + t.rows.front().buffer + ")";
    for (const std::string& h : std::vector<std::string>{metric, "95% CI", "GPU ms median", "95% CI"})
        header.push_back(h);
    if (time != "frame") header.push_back(time + " GPU ms median");
    header.emplace_back(time == "frame" ? "Pareto" : "Pareto (" + time + " ms)");
    auto line = [](const std::vector<std::string>& cells) {
        std::string s = "|";
        for (const auto& c : cells) s += " " + c + " |";
        return s + "\n";
    };
    out += line(header);
    std::string rule = "|";
    for (size_t i = 0; i < header.size(); ++i) rule += i <= t.axes.size() + (cameraColumn ? 1 : 0) ? " --- |" : " ---: |";
    out += rule + "\n";
    for (const TradeoffRow* r : rows) {
        std::vector<std::string> cells = {std::to_string(r->point)};
        cells.insert(cells.end(), r->axisValues.begin(), r->axisValues.end());
        if (cameraColumn) cells.push_back(r->camera);
        cells.push_back(number(r->error, "%.4g"));
        cells.push_back("[" + number(r->errorLo, "%.4g") + ", " + number(r->errorHi, "%.4g") + "]");
        cells.push_back(number(r->frameGpuMs, "%.3f"));
        cells.push_back("[" + number(r->frameGpuMsLo, "%.3f") + ", " + number(r->frameGpuMsHi, "%.3f") + "]");
        if (time != "frame") cells.push_back(number(t.passGpuMs(*r, time), "%.3f"));
        cells.emplace_back(r->pareto ? "**front**" : "");
        out += line(cells);
    }
    return out;
}

std::string what(const TradeoffTable& t, const std::string& against, const std::string& time = "frame") {
    const std::vector<const TradeoffRow*> rows = shownRows(t);
    const bool several = !rows.empty() && rows.front()->camera == TradeoffTable::kAllCameras;
    const std::string metric = t.rows.empty() ? "?" : t.rows.front().metric;
    return "Each row: a point of the sweep" + std::string(several ? " over every camera" : "") + ". " + metric +
           " of the buffer against " + against + " (" +
           (TradeoffTable::lowerIsBetter(metric) ? "lower" : "higher") + " is better)" +
           (several ? ", the mean over the cameras, its 95% interval a bootstrap over the cameras"
                    : ", its 95% interval a bootstrap over 16x16-pixel tiles") +
           "; GPU ms: the median frame time over the counted frames, 95% bootstrap interval of the median; "
           "front: on the Pareto front of " + (time == "frame" ? std::string("frame") : "the " + time + " pass's median") +
           " GPU ms against error (no other point is as fast and as accurate)" +
           (!t.rows.empty() && t.rows.front().buffer.find(":shadow_edges") != std::string::npos
                ? "; the error only over the pixels within 2 px of an edge of the reference's shadow buffer"
                : "") +
           ".\n";
}

int writePlot(const std::string& csv, const std::string& png, int width, int height, const std::string& time) {
    if (!runPlotScript("tradeoff_plot.py", "DW_TRADEOFF_PLOT_SCRIPT",
                       {"--csv", csv, "--out", png, "--size", std::to_string(width) + "x" + std::to_string(height),
                        "--time", time},
                       "tradeoff"))
        return 1;
    std::printf("wrote %s (%dx%d)\n", png.c_str(), width, height);
    return 0;
}

void checkPlot(const std::string& plot, int width, int height) {
    std::string ext = plot.size() >= 4 ? plot.substr(plot.size() - 4) : "";
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext != ".png") throw UsageError("--plot writes a PNG; give a file name ending in .png, got '" + plot + "'");
    if (width < 50 || height < 50)
        throw UsageError("--plot-size expects at least 50x50, got " + std::to_string(width) + "x" + std::to_string(height));
}

bool isRecordFile(const std::string& path) {
    return path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
}

std::vector<std::string> listOf(const std::string& flag, const std::string& text) {
    try {
        return splitList(text, flag);
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

int runMerge(int argc, char** argv) {
    CommandLine cl(argc, argv, 3);
    if (cl.flag("--help")) {
        std::cout << kTradeoffUsage;
        return 0;
    }
    const auto out = cl.value("--out");
    const auto json = cl.value("--json");
    const auto plot = cl.value("--plot");
    const auto [plotW, plotH] = CommandLine::parseSize(cl.value("--plot-size").value_or("800x600"), "--plot-size");
    const std::string time = cl.value("--time").value_or("frame");
    cl.finish("tradeoff merge");
    const std::vector<std::string> inputs = cl.positional();
    if (inputs.empty()) throw UsageError("tradeoff merge needs the shards' CSV files");
    if (!out) throw UsageError("tradeoff merge needs --out FILE.csv");
    CommandLine::NamedFiles writes = {{"--out", *out}}, reads;
    if (json) writes.emplace_back("--json", *json);
    if (plot) writes.emplace_back("--plot", *plot);
    for (const auto& in : inputs) reads.emplace_back("the shard " + in, in);
    CommandLine::requireDistinctFiles(writes, reads);
    if (plot) checkPlot(*plot, plotW, plotH);
    CommandLine::requireWritable(*out, "merged CSV");
    // Each shard as its CSV or its record (tradeoff --json).
    std::vector<TradeoffTable> parts;
    BenchFields settings;
    for (const auto& in : inputs) {
        if (isRecordFile(in)) {
            const ExperimentRecord r = ExperimentRecord::read(in);
            if (r.command != "tradeoff") throw FileError(in, "a " + r.command + " record, not a tradeoff's");
            parts.push_back(r.tradeoffTable(in));
            if (settings.empty() && r.tradeoffResults.contains("settings"))
                for (const auto& [k, v] : r.tradeoffResults["settings"].items())
                    if (v.is_string() && k != "shard" && k != "command") settings.emplace_back(k, v.get<std::string>());
        } else {
            parts.push_back(TradeoffTable::readCsv(in));
        }
    }
    const TradeoffTable all = TradeoffTable::merge(parts, inputs, time);
    std::string from;
    for (const auto& in : inputs) from += (from.empty() ? "" : " ") + in;
    std::printf("## tradeoff merge: %zu row(s) from %zu shard(s)\n\n%s\n%s\n", all.rows.size(), inputs.size(),
                what(all, "what the shards measured against", time).c_str(), markdown(all, time).c_str());
    std::fflush(stdout);
    all.writeCsv(*out);
    settings.emplace_back("merged_from", from);
    if (json) writeBenchFile(*json, ExperimentRecord::forTradeoffTable(all, settings).json(), "tradeoff record");
    std::printf("wrote %s%s\n", out->c_str(), json ? (", " + *json).c_str() : "");
    return plot ? writePlot(*out, *plot, plotW, plotH, time) : 0;
}

}  // namespace

int runTradeoffCommand(int argc, char** argv) {
    if (argc > 2 && std::string(argv[2]) == "merge") return runMerge(argc, argv);
    CommandLine cl(argc, argv, 2);
    if (cl.flag("--help")) {
        std::cout << kTradeoffUsage;
        return 0;
    }
    TradeoffOptions o;
    o.run = cl.runConfig();
    const auto [w, h] = CommandLine::parseSize(cl.value("--size").value_or("640x360"));
    o.run.width = w;
    o.run.height = h;
    for (const auto& s : cl.values("--sweep")) {
        BenchKnobAxis axis;
        try {
            axis = BenchGrid::parseSweep(s);
        } catch (const Error& e) {
            throw UsageError(e.what());
        }
        o.sweep.axes.push_back({axis.knob, axis.values});
    }
    if (const auto presets = cl.value("--presets")) {
        TradeoffAxis axis{"preset", listOf("--presets", *presets)};
        o.sweep.axes.insert(o.sweep.axes.begin(), std::move(axis));
    }
    const auto knobs = cl.value("--knobs");
    if (knobs && *knobs != "speed/quality")
        throw UsageError("--knobs: the only set is speed/quality (the knobs marked as trading speed for quality), got '" +
                         *knobs + "'");
    if (knobs && !o.sweep.axes.empty()) throw UsageError("--knobs speed/quality sweeps its own axes; give it without --sweep or --presets");
    const std::vector<std::string> excludes = cl.values("--exclude");
    for (const auto& e : excludes) {
        try {
            o.sweep.exclusion.add(e);
        } catch (const Error& err) {
            throw UsageError(err.what());
        }
    }
    const std::string against = cl.value("--against").value_or("reference");
    if (against != "reference") o.against = listOf("--against", against);
    o.metric = cl.value("--metric").value_or("flip");
    o.buffer = cl.value("--buffer").value_or("final");
    o.mask = cl.value("--mask").value_or("");
    o.time = cl.value("--time").value_or("frame");
    const int aoRays = CommandLine::parseInt("--ao-rays", cl.value("--ao-rays").value_or("64"), limits::kAoRays.min, limits::kAoRays.max);
    if (const auto orbit = cl.value("--orbit")) o.orbit = CommandLine::parseInt("--orbit", *orbit, limits::kTradeoffOrbit.min, limits::kTradeoffOrbit.max);
    o.walkthrough = cl.flag("--walkthrough");
    o.frames = CommandLine::parseInt("--frames", cl.value("--frames").value_or("5"), limits::kFrames.min, limits::kFrames.max);
    o.warmup = CommandLine::parseInt("--warmup", cl.value("--warmup").value_or("1"), limits::kWarmup.min, limits::kWarmup.max);
    o.block = CommandLine::parseInt("--block", cl.value("--block").value_or("1"), limits::kBlock.min, limits::kBlock.max);
    o.resamples = CommandLine::parseInt("--resamples", cl.value("--resamples").value_or("2000"), limits::kResamples.min, limits::kResamples.max);
    if (const auto shard = cl.value("--shard")) {
        try {
            o.shard = BenchShard::parse(*shard);
        } catch (const Error& e) {
            throw UsageError(e.what());
        }
    }
    const std::string suffix =
        o.shard.whole() ? "" : "-shard-" + std::to_string(o.shard.index) + "-of-" + std::to_string(o.shard.count);
    const std::string csv = cl.value("--csv").value_or("tradeoff" + suffix + ".csv");
    const std::string json = cl.value("--json").value_or("tradeoff" + suffix + ".json");
    const std::string plot = cl.value("--plot").value_or("tradeoff" + suffix + ".png");
    const auto [plotW, plotH] = CommandLine::parseSize(cl.value("--plot-size").value_or("800x600"), "--plot-size");
    const bool quiet = cl.flag("--quiet");
    cl.finish("tradeoff");
    if (!cl.positional().empty()) throw UsageError("tradeoff: unexpected argument '" + cl.positional()[0] + "'");
    if (o.sweep.axes.empty() && !knobs)
        throw UsageError("tradeoff needs axes: --sweep knob=v1,v2,..., --presets A,B,... or --knobs speed/quality");
    CommandLine::requireDistinctFiles({{"--csv", csv}, {"--json", json}, {"--plot", plot}}, CommandLine::inputFiles(o.run));
    checkPlot(plot, plotW, plotH);
    CommandLine::requireWritable(csv, "tradeoff CSV");
    CommandLine::requireWritable(json, "tradeoff JSON");
    CommandLine::requireWritable(plot, "plot");
    if (knobs) {
        // About the current settings: the run configuration's knobs on its scene.
        o.run.validate();
        const Scene scene = loadScene(o.run.sceneSpec());
        KnobRegistry current = RunConfig::declaredKnobs();
        o.run.applyKnobs(current, scene);
        GridExclusion exclusion = o.sweep.exclusion;
        o.sweep = TradeoffSweep::aroundCurrent(current);
        o.sweep.exclusion = exclusion;
    }

    // Everything that can fail without GL fails here: axes, values, presets, the scene.
    TradeoffRunner runner(o);
    for (const auto& wline : runner.scene().warnings) std::fprintf(stderr, "warning: %s\n", wline.c_str());
    TradeoffMeasurement measured = measureTradeoff(runner, aoRays, quiet);
    TradeoffResult& result = measured.result;
    const BenchFields& machine = measured.machine;
    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
    result.settings.emplace_back("command", command);

    const TradeoffTable& t = result.table;
    const std::string againstText = o.against.empty() ? "the CPU reference" : against;
    std::printf("## tradeoff: %s, %zu point(s) x %zu camera(s), %s of %s (%s) against %s\n\n%s\n%s\n",
                runner.scene().name.c_str(), runner.points().size(), runner.cameras().size(), o.metric.c_str(),
                o.buffer.c_str(), TradeoffRunner::gpuOutput(o.buffer).c_str(), againstText.c_str(),
                what(t, againstText, o.time).c_str(), markdown(t, o.time).c_str());
    std::fflush(stdout);
    t.writeCsv(csv);
    // The JSON is the experiment record (docs/records.md): replay runs it again.
    RecordedTradeoff recorded;
    recorded.options = o;
    recorded.exclude = excludes;
    recorded.aoRays = aoRays;
    recorded.runPreset = o.run.presetSpec();
    recorded.runSets = o.run.sets;
    writeBenchFile(json, ExperimentRecord::forTradeoff(recorded, runner.scene(), t, machine, result.settings).json(json),
                   "tradeoff record");
    std::printf("wrote %s, %s\n", csv.c_str(), json.c_str());
    if (t.rows.empty()) return 0;
    return writePlot(csv, plot, plotW, plotH, o.time);
}

}  // namespace dw
