#pragma once
// The numbers a `bench` run reports, made from its samples alone (so a
// merged set of shards gives the same table as one run): per configuration
// and per series (each pass, each span, the whole frame) the median, min, max
// and mean GPU and CPU milliseconds over its counted frames, and the ratio of
// one series' GPU median (the whole frame unless `bench --ratio-of` names a
// pass or span) to the baseline configuration's, with a bootstrap 95%
// interval.
// Shown as Markdown tables and written as JSON with every sample. Needs no GL.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "renderer/bench/BenchResults.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/graph/PassTimer.h"

namespace dw {

struct BenchSeriesStats {
    std::string series;
    TimingStats gpu, cpu;
};

struct BenchSummaryRow {
    int config = 0;
    std::vector<BenchSeriesStats> series;  // in recorded order; "frame" last
    const BenchSeriesStats* find(const std::string& name) const;
    const BenchSeriesStats* frame() const { return find(PassTimer::kFrameSeries); }
    int baseline = -1;    // the configuration it is compared with; -1: none in the results
    RatioInterval ratio;  // the ratio series' GPU median / the baseline's (invalid where either has none)
    // The frame's ratio beside it when the ratio series is not the frame (--ratio-of a pass).
    RatioInterval frameRatio;
};

struct BenchBaseline {
    std::string axis;   // "size", "lights" or a knob; empty: no axis to compare along
    std::string value;
    // The series whose GPU medians the ratios compare: "frame", a pass
    // ("lighting") or a span ("lighting/shadow maps").
    std::string series = PassTimer::kFrameSeries;
};

struct BenchSummary {
    BenchBaseline baseline;
    std::vector<BenchSummaryRow> rows;  // one per configuration, in index order
    std::vector<std::string> passes;    // every pass and span seen, in pipeline order (no "frame")
    const BenchSummaryRow* find(int config) const;
};

// `spec` is "axis=value" (--baseline), or empty: the first value of the first
// knob axis, else of lights, else of size (the first axis with more than one
// value; "first" = in the lowest-numbered configuration). Throws Error for an
// axis the results do not have or a value none of its configurations has.
BenchBaseline chooseBaseline(const BenchResults& results, const std::string& spec);
// The same rule over a whole grid, before it runs (a shard's results may lack
// the baseline's configurations; theirs then get no ratio).
BenchBaseline chooseBaseline(const BenchGrid& grid, int sceneLights, const std::string& spec);
// Whether some configuration of `results` has samples of `series`.
bool hasSeries(const BenchResults& results, const std::string& series);
BenchSummary summarize(const BenchResults& results, const BenchBaseline& baseline, int resamples = 2000,
                       std::uint64_t seed = 12345);

// The main table (one row per configuration: its axes, LPP, frames, frame
// GPU median/min/max, CPU median, ratio and 95% CI; the ratio's column names
// its series unless it is the frame, and then the frame's ratio and the
// series' own GPU median stand beside it, so the ratio matches a number of
// the table; "auto picked" when lighting.strategy=auto chose a strategy) and
// the per-pass table (GPU medians per pass and span; a pass named like an
// axis column is headed "<name> (pass)", so no two columns share a name).
// tableCaption says in one line what a table's numbers are.
std::string markdownTable(const BenchResults& results, const BenchSummary& summary);
std::string markdownPassTable(const BenchResults& results, const BenchSummary& summary);
std::string mainTableCaption(const BenchSummary& summary, int resamples);
std::string passTableCaption();
// LPP as the tables print it: two decimals, or two significant digits below 0.005 (0.0012, not 0.00).
std::string lppText(double lpp);

// bench's results: {"tool", "machine", "settings", "axes", "baseline"
// ({axis, value, series} or null), "configs": [{config, size, width, height,
// lights, knobs, lpp, lpp_lit, frames, series: {name: {gpu_ms: {median, min,
// max, mean, frames, ci95 (the median's bootstrap 95% interval)}, cpu_ms}},
// ratio, ci95, baseline_config, stats: {pass: line} (when recorded), samples:
// [{sample, seq, frame, gpu_ms: {series: ms}, cpu_ms: {...}}]}]}: the
// `results` of a bench experiment record (renderer/record/ExperimentRecord).
nlohmann::ordered_json benchResultsJson(const BenchResults& results, const BenchSummary& summary);
// The summary a bench JSON holds: an experiment record's `results`, or the
// file itself when it was written before records (for bench merge's readers).
const nlohmann::json& benchSummaryOf(const nlohmann::json& file);

}  // namespace dw
