// deferred-workbench tradeoff: what each setting costs in GPU milliseconds
// and in error against the CPU reference (or a named configuration), and
// which settings are on the Pareto front; `tradeoff merge` joins shards.
// docs/tradeoffs.md says how to run it and what each column means.
#include <climits>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "app/Commands.h"
#include "app/HostInfo.h"
#include "app/StudyOptions.h"
#include "app/SweepOptions.h"
#include "headless/CommandLine.h"
#include "headless/HeadlessGlContext.h"
#include "headless/PlotScript.h"
#include "renderer/Error.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/bench/BudgetPick.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/bench/TradeoffShards.h"
#include "renderer/study/TradeoffStudy.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

// What tradeoff's shared options (SweepOptions) mean here.
const SweepCommand kTradeoff = [] {
    SweepCommand c;
    c.name = "tradeoff";
    c.frames = 5;
    c.plotSize = "800x600";
    c.plotByDefault = true;
    c.sweepWhat = "an axis: a knob (ssao.samples=8,16,32), camera.near=... or camera.far=...; the full\n"
                  "               grid of every --sweep and --presets";
    c.camerasWhat = "several cameras add a row per point over all of them";
    c.shardWhat = "the points whose number % n == i";
    c.filesWhat = "the table, and an experiment record (deferred-workbench replay runs it again;\n"
                  "               tradeoff merge reads shards' CSVs or records)";
    c.plotWhat = "time against error with both intervals, the front labelled, by scripts/tradeoff_plot.py\n"
                 "               (python3-matplotlib); default tradeoff.png";
    return c;
}();

std::string tradeoffUsage() {
    return "usage: deferred-workbench tradeoff [--scene S] [--preset P] [--set knob=value]... [--size WxH]\n"
           "                                   [--sweep axis=v1,v2,...]... [--presets A,B,...] [--knobs speed/quality]\n"
           "                                   [--study [NAME:]KNOB=V1,V2[:KNOB=V...]]... [--study-file F.json]\n"
           "                                   [--exclude axis=v[,v...][,axis=v...]]... [--against reference|knob=v[,knob=v...]]\n"
           "                                   [--metric flip|rms|psnr|ssim|temporal] [--buffer final|lbuffer|ao|shadow] [--ao-rays N]\n"
           "                                   [--ref-spp N] [--ref-filter box|tent] [--mask shadow_edges] [--time frame|PASS[+PASS...]] [--cost gpu_ms|COUNTER]\n"
           "                                   [--budget-ms X | --budget N] [--search [--max-evals N]] [--no-counters]\n"
           "                                   [--orbit N [--orbit-degrees D] | --walkthrough] [--frames N] [--warmup N] [--block K] [--resamples N]\n"
           "                                   [--shard i/n] [--csv FILE] [--record FILE] [--plot FILE.png] [--plot-size WxH]\n"
           "                                   [--quiet]\n"
           "       deferred-workbench tradeoff merge SHARD.csv|SHARD.json... --out ALL.csv [--record FILE] [--plot FILE.png] [--plot-size WxH]\n"
           "                                   [--time frame|PASS[+PASS...]] [--cost gpu_ms|COUNTER] [--budget-ms X | --budget N]\n"
           "  --animation  which glTF animation clip plays: a clip's name or index (0-based over the scene's\n"
           "               clips), or none; default each file's first (docs/scene-format.md, \"Animation\")\n"
           "  --presets    presets as an axis (the column 'preset'): each point's knobs are the preset's, under --set\n"
           "  --knobs speed/quality  every knob the registry marks as trading speed for quality, one at a time\n"
           "               about the current settings (docs/tradeoffs.md says which values)\n" +
           StudyOptions::help() +
           "  --against    what the error is measured against: the CPU reference (default; from the reference\n"
           "               cache, each camera's rendered once) or the point with these knob values on top\n"
           "  --metric     the error (default flip); --buffer the image it is measured on (default final;\n"
           "               ao = the AO buffer the lighting pass reads (ao.filtered); shadow = lighting.shadow, the\n"
           "               shadow factor as the reference's shadow buffer defines it); --ao-rays the reference's AO\n"
           "               rays per pixel (default 64); temporal: the temporal error (docs/metrics.md) of the\n"
           "               camera path's frames (--orbit N >= 2 or --walkthrough, required), each point rendering\n"
           "               them in order after 16 frames at the first camera, against the reference's frames of\n"
           "               the same cameras; on the all-cameras row (a camera's row has no error)\n"
           "  --ref-spp    the reference's samples per pixel (default 1: the pixel's centre), as reference --spp:\n"
           "               N points over the pixel, the footprint truth texture filters are measured against;\n"
           "               --ref-filter box (default) or tent, as reference --filter; both in the cache key\n"
           "  --mask shadow_edges  the error over the pixels within 2 px of an edge of the reference's shadow\n"
           "               buffer only; the buffer column reads <buffer>:shadow_edges\n"
           "  --time       what the front ranks by: frame (default, frame_gpu_ms) or a pass (its gpu_ms.<pass>),\n"
           "               since on llvmpipe the frame time drowns a small pass's; with shadows.reuse_map on\n"
           "               the maps are drawn in the lighting pass: \"lighting/shadow maps\" ranks by them;\n"
           "               a sum of passes (lighting+ao+ao_filter) ranks by the median of each frame's sum\n"
           "  --cost       the front's cost axis: gpu_ms (default, the time --time names) or a counter of that\n"
           "               span (fragments, samples, primitives, vertices, compute, bytes: exact, no interval);\n"
           "               refused where the driver lacks it (GL_ARB_pipeline_statistics_query)\n"
           "  --budget-ms  prints pick: the least-error point whose --time's 95% interval ends under X ms,\n"
           "               and the points that fit but cannot be told apart from it in error (whatever --cost)\n"
           "  --budget     with a counter --cost: the pick by that counter (exact) under N in its own unit;\n"
           "               not with --budget-ms\n"
           "  --search     with a budget, instead of a grid: coordinate descent over the speed/quality knobs from\n"
           "               the current settings to the least error under it (a move only when the pick is told\n"
           "               apart from the current value in error); every evaluation a row of the CSV\n"
           "  --max-evals  the search's bound in evaluations (points measured; default 48)\n"
           "  --no-counters  measure without the per-pass cost counters (their columns are left out)\n"
           "  --size       the render size (default 640x360)\n"
           "  --orbit-degrees  the arc --orbit N's cameras span, D / N degrees apart (default 360: evenly all\n"
           "               around); a few degrees make a path of small steps for --metric temporal\n" +
           SweepOptions::help(kTradeoff) + SweepMergeOptions::help(kTradeoff) + CommandLine::rangesHelp("tradeoff") +
           CommandLine::rangesHelp("tradeoff merge");
}

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

// With shadows.reuse_map on the shadows pass draws no map (each is drawn
// just before its light is shaded, in that pass's span PASS/shadow maps):
// its near-zero time is true, and said where it is shown.
std::string reusedMaps(const TradeoffTable& t, const TradeoffRow& r, const std::string& time) {
    if (time != "shadows") return "";
    static const std::string kMaps = "/shadow maps";
    for (const auto& p : t.passes)
        if (p.size() > kMaps.size() && p.compare(p.size() - kMaps.size(), std::string::npos, kMaps) == 0 &&
            p.rfind("shadows/", 0) != 0 && std::isfinite(t.passGpuMs(r, p)))
            return " (reused: maps in " + p + ", " + number(t.passGpuMs(r, p), "%.3f") + ")";
    return "";
}

// The front column: **front** (pareto), indistinguishable, or "dominated by 0, 2".
std::string frontCell(const TradeoffRow& r) {
    if (r.front == "pareto" || (r.front.empty() && r.pareto)) return "**front**";
    if (r.front != "dominated") return r.front;
    std::string by;
    for (int p : r.dominatedBy) by += (by.empty() ? "" : ", ") + std::to_string(p);
    return "dominated by " + by;
}

// "1 (error), 3 (both)".
std::string tiesCell(const TradeoffRow& r) {
    std::string s;
    for (const auto& [p, axes] : r.tiedWith) s += (s.empty() ? "" : ", ") + std::to_string(p) + " (" + axes + ")";
    return s;
}

// After the table: how the front was decided, what cannot be told apart, and the pick.
std::string frontLines(const TradeoffTable& t, const BudgetPick* pick, const std::string& time, const std::string& cost) {
    if (t.rows.empty()) return "";
    const std::string camera = BudgetPicker::shownCamera(t);
    std::string out;
    const auto rule = t.frontRules.find(camera);
    if (rule != t.frontRules.end()) out += "front: " + rule->second + "\n";
    const std::string costName = cost == "gpu_ms" ? "time" : time == "frame" ? cost : cost + "." + time;
    for (const auto& l : t.frontSummary(camera, costName)) out += "front: " + l + "\n";
    if (pick)
        for (const auto& l : pick->lines) out += l + "\n";
    return out.empty() ? "" : out + "\n";
}

std::string markdown(const TradeoffTable& t, const std::string& time = "frame", const std::string& cost = "gpu_ms") {
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
    if (time != "frame") {
        header.push_back(time + " GPU ms median");
        header.emplace_back("95% CI");
    }
    // A counter as the cost axis: its value (exact, no interval) of the span --time names.
    const bool counter = cost != "gpu_ms";
    const std::string span = time == "frame" ? cost : cost + "." + time;
    if (counter) header.push_back(span + " (exact)");
    header.emplace_back(counter ? "Pareto (" + span + ")" : time == "frame" ? "Pareto" : "Pareto (" + time + " ms)");
    header.emplace_back("tied with");
    auto line = [](const std::vector<std::string>& cells) {
        std::string s = "|";
        for (const auto& c : cells) s += " " + c + " |";
        return s + "\n";
    };
    out += line(header);
    std::string rule = "|";
    for (size_t i = 0; i < header.size(); ++i)
        rule += i <= t.axes.size() + (cameraColumn ? 1 : 0) || i + 2 >= header.size() ? " --- |" : " ---: |";
    out += rule + "\n";
    for (const TradeoffRow* r : rows) {
        std::vector<std::string> cells = {std::to_string(r->point)};
        cells.insert(cells.end(), r->axisValues.begin(), r->axisValues.end());
        if (cameraColumn) cells.push_back(r->camera);
        cells.push_back(number(r->error, "%.4g"));
        cells.push_back("[" + number(r->errorLo, "%.4g") + ", " + number(r->errorHi, "%.4g") + "]");
        cells.push_back(number(r->frameGpuMs, "%.3f"));
        cells.push_back("[" + number(r->frameGpuMsLo, "%.3f") + ", " + number(r->frameGpuMsHi, "%.3f") + "]");
        if (time != "frame") {
            cells.push_back(number(t.timeOf(*r, time), "%.3f") + reusedMaps(t, *r, time));
            cells.push_back(time == t.time ? "[" + number(r->timeMsLo, "%.3f") + ", " + number(r->timeMsHi, "%.3f") + "]" : "-");
        }
        if (counter) cells.push_back(number(t.costOf(*r, time, cost), "%.0f"));
        cells.push_back(frontCell(*r));
        cells.push_back(tiesCell(*r));
        out += line(cells);
    }
    return out;
}

std::string what(const TradeoffTable& t, const std::string& against, const std::string& time = "frame",
                 const std::string& cost = "gpu_ms") {
    const std::vector<const TradeoffRow*> rows = shownRows(t);
    const bool several = !rows.empty() && rows.front()->camera == TradeoffTable::kAllCameras;
    const std::string metric = t.rows.empty() ? "?" : t.rows.front().metric;
    return "Each row: a point of the sweep" + std::string(several ? " over every camera" : "") + ". " + metric +
           " of the buffer against " + against + " (" +
           (TradeoffTable::lowerIsBetter(metric) ? "lower" : "higher") + " is better)" +
           (metric == "temporal" ? ", the temporal error of the path's frames rendered in order (docs/metrics.md), its 95% "
                                   "interval a bootstrap over the frame pairs"
            : several           ? ", the mean over the cameras, its 95% interval a bootstrap over the cameras"
                                : ", its 95% interval a bootstrap over 16x16-pixel tiles") +
           "; GPU ms: the median frame time over the counted frames, 95% bootstrap interval of the median; "
           "Pareto: **front** on the front of " +
           (cost != "gpu_ms"
                ? (time == "frame" ? "the frame's " + cost : "the " + time + " " + cost) +
                      " (a cost counter: exact, the same every frame; only the errors are tested)"
                : "the medians of " + (time == "frame" ? std::string("frame") : time == t.time && time.find('+') != std::string::npos
                                                                ? "the per-frame sum " + time
                                                                : "the " + time + " pass's") +
                      " GPU ms") +
           " against the errors (no other point is as cheap and as accurate); indistinguishable: off it, but no "
           "front point beats it on both axes with confidence; dominated by: the front points that do; tied with: the "
           "other points it cannot be told apart from on that axis" +
           (!t.rows.empty() && t.rows.front().buffer.find(":shadow_edges") != std::string::npos
                ? "; the error only over the pixels within 2 px of an edge of the reference's shadow buffer"
                : "") +
           ".\n";
}

int writePlot(const std::string& csv, const std::string& png, int width, int height, const std::string& time,
              const std::string& cost = "gpu_ms") {
    if (!runPlotScript("tradeoff_plot.py", "DW_TRADEOFF_PLOT_SCRIPT",
                       {"--csv", csv, "--out", png, "--size", std::to_string(width) + "x" + std::to_string(height),
                        "--time", time, "--cost", cost},
                       "tradeoff"))
        return 1;
    std::printf("wrote %s (%dx%d)\n", png.c_str(), width, height);
    return 0;
}

bool isRecordFile(const std::string& path) {
    return path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
}

// What an input of `tradeoff merge` says of the run it comes from
// (TradeoffShards): the fields its rows hold, and its record's grid (the
// input itself, or <name>.json beside a CSV) when there is one.
TradeoffShardInput shardInput(const std::string& name, const TradeoffTable& t) {
    TradeoffShardInput in;
    in.name = name;
    std::set<std::string> metrics, buffers, cameras;
    for (const auto& r : t.rows) {
        metrics.insert(r.metric);
        buffers.insert(r.buffer);
        if (r.camera != TradeoffTable::kAllCameras) cameras.insert(r.camera);
    }
    auto joined = [](const std::set<std::string>& s) {
        std::string text;
        for (const auto& v : s) text += (text.empty() ? "" : ",") + v;
        return text;
    };
    std::string axes;
    for (const auto& a : t.axes) axes += (axes.empty() ? "" : ",") + a;
    in.fields.emplace_back("axes", axes);
    if (!t.rows.empty()) {
        in.fields.emplace_back("metric", joined(metrics));
        in.fields.emplace_back("buffer", joined(buffers));
        in.fields.emplace_back("cameras", std::to_string(cameras.size()) + " (" + joined(cameras) + ")");
    }
    const std::string record =
        isRecordFile(name) ? name : std::filesystem::path(name).replace_extension(".json").string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(record, ec)) return in;
    const nlohmann::json j = readJsonFile(record, {kMaxJsonDepth, false});
    if (!j.is_object() || j.value("command", std::string()) != "tradeoff") return in;
    if (j.contains("size") && j["size"].is_array() && j["size"].size() == 2)
        in.fields.emplace_back("size", j["size"][0].dump() + "x" + j["size"][1].dump());
    if (!j.contains("grid") || !j["grid"].is_object() || j["grid"].contains("merged")) return in;
    const nlohmann::json& g = j["grid"];
    auto text = [&](const char* key) { return g.contains(key) ? (g[key].is_string() ? g[key].get<std::string>() : g[key].dump()) : ""; };
    if (g.contains("against")) in.fields.emplace_back("against", text("against").empty() || text("against") == "[]" ? "reference" : text("against"));
    nlohmann::json grid = nlohmann::json::object();
    for (const char* key : {"axes", "one_at_a_time", "centre", "points", "exclude"})
        if (g.contains(key)) grid[key] = g[key];
    in.fields.emplace_back("grid", grid.dump());
    in.fields.emplace_back("camera path", "orbit " + text("orbit") + ", walkthrough " + text("walkthrough"));
    in.shard = text("shard");
    return in;
}

// The runner's options; a bad --study (an unknown knob, a value it does not
// take, a point twice) is a usage error, as the flags' other checks are.
TradeoffOptions studyOptions(const TradeoffStudyOptions& s) {
    try {
        return TradeoffStudy::runnerOptions(s);
    } catch (const TradeoffStudyError& e) {
        throw UsageError(e.what());
    }
}

// tradeoff merge --budget-ms X / --budget N: as a run refuses them (one of the two; --budget with a counter --cost).
void checkMergeBudget(const std::optional<double>& budgetMs, const std::optional<double>& budget, const std::string& cost) {
    if (budgetMs && budget) throw UsageError("--budget-ms and --budget: give one (--budget-ms bounds the time in ms, --budget the --cost counter)");
    if (budget && cost == "gpu_ms")
        throw UsageError("--budget bounds a counter: give --cost fragments|samples|primitives|vertices|compute|bytes (for time, --budget-ms)");
    try {
        if (budgetMs) BudgetPicker::check(*budgetMs);
        if (budget) BudgetPicker::check(*budget, "--budget");
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

// The pick over the merged rows: fits by the time's 95% interval as a run's pick; told apart in error by the
// merge's intervals rule (ConfidentFront: 95% intervals that do not overlap, no paired draws across shards).
std::optional<BudgetPick> mergedPick(TradeoffTable& all, const std::optional<double>& budgetMs,
                                     const std::optional<double>& budget, const std::string& cost) {
    if (all.rows.empty() || (!budgetMs && !budget)) return std::nullopt;
    const std::string camera = BudgetPicker::shownCamera(all);
    BudgetPick pick = budgetMs ? BudgetPicker::pick(all, *budgetMs, camera)
                               : BudgetPicker::pick(all, *budget, camera, BudgetPicker::counterCost(all, cost));
    pick.lines.push_back("pick: over the merged shards the error ties are the intervals rule's (95% intervals that "
                         "overlap; the shards' paired draws are not kept): conservative, it ties more than one run");
    return pick;
}

// Runs `f`; a bad --time or --cost it finds (an Error naming the flag: a
// pass the pipeline or the shards lack, a sum the rows do not carry) is a
// usage error (exit 2), as the flags' other checks are.
template <typename F>
auto asUsage(F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        const std::string what = e.what();
        if (what.rfind("--time ", 0) == 0 || what.rfind("--cost ", 0) == 0) throw UsageError(what);
        throw;
    }
}

// The time a merge ranks by: the shards' CSV time column (what their runs
// ranked by) unless --time names another, which is said; frame when the
// shards disagree and --time is not given.
std::string mergeTime(const std::vector<TradeoffTable>& parts, const std::optional<std::string>& given) {
    std::string carried = parts.empty() ? "" : parts.front().time;
    for (const auto& part : parts)
        if (part.time != carried) carried.clear();
    if (!given) return carried.empty() ? "frame" : carried;
    try {
        (void)TradeoffTable::timeTerms(*given);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    if (!carried.empty() && *given != carried)
        std::fprintf(stderr, "tradeoff merge: note: --time %s ranks by another time than the shards' (their time column "
                             "is %s)\n", given->c_str(), carried.c_str());
    return *given;
}

// --budget-ms fits by the time's 95% interval: a time the rows carry without
// one (a single pass's median, not the runs' --time) can never fit, so it is refused.
void checkBudgetInterval(const TradeoffTable& all, const std::string& time) {
    for (const auto& r : all.rows)
        if (std::isfinite(r.timeMsHi)) return;
    throw UsageError("--budget-ms: the time " + time + " has no interval in these shards (only a run's --time carries "
                     "one; a single pass's column is its median): merge with the runs' --time, or run tradeoff --time " + time);
}

int runMerge(int argc, char** argv) {
    CommandLine cl(argc, argv, 3, "tradeoff merge");
    if (cl.flag("--help")) {
        std::cout << tradeoffUsage();
        return 0;
    }
    SweepMergeOptions m = SweepMergeOptions::read(cl, kTradeoff);
    const std::optional<std::string> timeGiven = cl.value("--time");
    const std::string cost = cl.value("--cost").value_or("gpu_ms");
    const std::optional<double> budgetMs = cl.real("--budget-ms"), budget = cl.real("--budget");
    cl.finish("tradeoff merge");
    if (!TradeoffTable::isCost(cost))
        throw UsageError("--cost: expected one of " + TradeoffTable::costNames() + ", got '" + cost + "'");
    checkMergeBudget(budgetMs, budget, cost);
    m.check(cl, kTradeoff);
    const std::vector<std::string>& inputs = m.inputs;
    const std::string& out = *m.out;
    const std::optional<std::string>& json = m.json;
    const std::optional<std::string>& plot = m.plot;
    const int plotW = m.plotWidth, plotH = m.plotHeight;
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
    // Shards of other runs are refused, missing shards said (as bench merge does).
    std::vector<TradeoffShardInput> described;
    for (size_t i = 0; i < inputs.size(); ++i) described.push_back(shardInput(inputs[i], parts[i]));
    for (const auto& w : TradeoffShards::check(described)) std::fprintf(stderr, "tradeoff merge: warning: %s\n", w.c_str());
    const std::string time = mergeTime(parts, timeGiven);
    TradeoffTable all = asUsage([&] { return TradeoffTable::merge(parts, inputs, time, cost); });
    if (budgetMs) checkBudgetInterval(all, time);
    const std::optional<BudgetPick> pick = mergedPick(all, budgetMs, budget, cost);
    std::string from;
    for (const auto& in : inputs) from += (from.empty() ? "" : " ") + in;
    std::printf("## tradeoff merge: %zu row(s) from %zu shard(s)\n\n%s\n%s\n%s", all.rows.size(), inputs.size(),
                what(all, "what the shards measured against", time, cost).c_str(), markdown(all, time, cost).c_str(),
                frontLines(all, pick ? &*pick : nullptr, time, cost).c_str());
    std::fflush(stdout);
    all.writeCsv(out);
    settings.emplace_back("merged_from", from);
    if (pick) {  // as a run's record keeps them
        settings.emplace_back(budgetMs ? "budget_ms" : "budget", number(pick->budgetMs, "%.6g") + (budgetMs ? "" : " " + cost));
        for (const auto& line : pick->lines) settings.emplace_back("pick", line);
    }
    if (json) writeBenchFile(*json, ExperimentRecord::forTradeoffTable(all, settings).json(*json), "tradeoff record");
    std::printf("wrote %s%s\n", out.c_str(), json ? (", " + *json).c_str() : "");
    return plot ? writePlot(out, *plot, plotW, plotH, time, cost) : 0;
}

}  // namespace

int runTradeoffCommand(int argc, char** argv) {
    if (argc > 2 && std::string(argv[2]) == "merge") return runMerge(argc, argv);
    for (int i = 2; i < argc; ++i)
        if (std::string(argv[i]) == "--attribute") return runTradeoffAttribute(argc, argv);
    CommandLine cl(argc, argv, 2, "tradeoff");
    if (cl.flag("--help")) {
        std::cout << tradeoffUsage();
        return 0;
    }
    // The shared options as bench reads them (SweepOptions), the rest here; then
    // TradeoffStudy checks them all, as it does the Python module's.
    const SweepOptions so = SweepOptions::read(cl, kTradeoff);
    TradeoffStudyOptions s;
    s.run = cl.runConfig();
    s.run.sceneTime = cl.real("--scene-time").value_or(0.0);
    const auto [w, h] = SweepOptions::readSizes(cl, false).front();
    s.run.width = w;
    s.run.height = h;
    s.sweep = so.sweeps;
    if (const auto presets = cl.value("--presets")) s.presets = CommandLine::parseList("--presets", *presets);
    s.knobs = cl.value("--knobs").value_or("");
    const StudyOptions studies = StudyOptions::read(cl);
    s.studies = studies.studies;
    s.exclude = so.excludes;
    s.against = cl.value("--against").value_or("reference");
    s.metric = cl.value("--metric").value_or("flip");
    s.buffer = cl.value("--buffer").value_or("final");
    s.mask = cl.value("--mask").value_or("");
    s.time = cl.value("--time").value_or("frame");
    s.budgetMs = cl.real("--budget-ms");
    s.budget = cl.real("--budget");
    s.cost = cl.value("--cost").value_or("gpu_ms");
    s.counters = !cl.flag("--no-counters");
    s.search = cl.flag("--search");
    const std::optional<int> maxEvals = cl.whole("--max-evals");
    s.aoRays = cl.whole("--ao-rays", 64);
    s.refSpp = cl.whole("--ref-spp", 1);
    s.refFilter = cl.value("--ref-filter").value_or("box");
    s.orbit = so.orbit;
    s.orbitDegrees = cl.real("--orbit-degrees").value_or(360.0);
    s.walkthrough = so.walkthrough;
    s.frames = so.frames;
    s.warmup = so.warmup;
    s.block = so.block;
    s.resamples = so.resamples;
    s.shard = so.shard.whole() ? "" : so.shardText();
    const std::string& csv = so.csv;
    const std::string& json = so.json;
    const std::optional<std::string>& plot = so.plot;  // none with --plot none
    const int plotW = so.plotWidth, plotH = so.plotHeight;
    const bool quiet = so.quiet;
    cl.finish("tradeoff");
    if (!cl.positional().empty()) throw UsageError("tradeoff: unexpected argument '" + cl.positional()[0] + "'");
    if (maxEvals && !s.search) throw UsageError("--max-evals bounds --search; give --search with it");
    s.maxEvals = maxEvals.value_or(s.maxEvals);
    try {
        (void)TradeoffTable::timeTerms(s.time);
        (void)TradeoffStudy::check(s);
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    CommandLine::NamedFiles reads = CommandLine::inputFiles(s.run);
    if (studies.file) reads.emplace_back("--study-file", *studies.file);
    so.checkOutputs(kTradeoff, reads);
    const TradeoffOptions o = studyOptions(s);  // --knobs speed/quality or --study: its axes, from the scene
    std::string command;
    for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
    if (s.search) return runTradeoffSearch(s, o, so, command);

    // Everything that can fail without GL fails here: axes, values, presets, the scene.
    TradeoffRunner runner(o);
    for (const auto& wline : runner.scene().warnings) std::fprintf(stderr, "warning: %s\n", wline.c_str());
    auto context = HeadlessGlContext::create();
    TradeoffStudyProgress progress;
    if (!quiet) progress.line = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    progress.warning = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    TradeoffMeasurement measured =
        asUsage([&] { return TradeoffStudy::measure(runner, s.aoRays, context->platform(), progress, 1,
                                                          TradeoffStudy::referencePixels(s)); });
    // The JSON is the experiment record (docs/records.md): replay runs it again.
    const ExperimentRecord record = TradeoffStudy::record(s, o, runner, measured, command);
    const TradeoffResult& result = measured.result;
    const std::string against = s.against;

    const TradeoffTable& t = result.table;
    const std::string againstText = o.against.empty() ? "the CPU reference" : against;
    std::printf("## tradeoff: %s, %zu point(s) x %zu camera(s), %s of %s (%s) against %s\n\n%s\n%s\n%s",
                runner.scene().name.c_str(), runner.points().size(), runner.cameras().size(), o.metric.c_str(),
                o.buffer.c_str(), TradeoffRunner::gpuOutput(o.buffer).c_str(), againstText.c_str(),
                what(t, againstText, o.time, o.cost).c_str(), markdown(t, o.time, o.cost).c_str(),
                frontLines(t, o.budgetMs > 0.0 || o.budget > 0.0 ? &result.pick : nullptr, o.time, o.cost).c_str());
    std::fflush(stdout);
    t.writeCsv(csv);
    writeBenchFile(json, record.json(json), "tradeoff record");
    std::printf("wrote %s, %s\n", csv.c_str(), json.c_str());
    if (t.rows.empty() || !plot) return 0;
    return writePlot(csv, *plot, plotW, plotH, o.time, o.cost);
}

}  // namespace dw
