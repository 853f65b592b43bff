#pragma once
// What a `tradeoff` run found, in the form it is written and read back (the
// tradeoff CSV): one row per point of the sweep and camera, with what the
// point costs (GPU milliseconds, per frame and per pass, with the frame's
// bootstrap interval) and how far its image is from the one it is measured
// against (the error and its interval), and whether it is on the Pareto front.
//
// Columns, in this order:
//   point                      the point's number in the sweep (0, 1, ...)
//   <axis>...                  one per swept axis, under its own name: a knob
//                              ("ssao.samples"), "preset", "camera.near", "camera.far"
//   camera                     the camera: "0", "1", ... or "all" (the row over
//                              every camera of that point)
//   metric                     flip | rms | psnr | ssim
//   buffer                     lbuffer | final | ao | shadow (as asked for); with
//                              --mask shadow_edges "<buffer>:shadow_edges" (the
//                              error over the pixels near a reference shadow edge)
//   error,error_lo,error_hi    the metric and its interval (empty: not measured)
//   frames                     counted frames behind the times
//   frame_gpu_ms,frame_gpu_ms_lo,frame_gpu_ms_hi
//                              the median GPU frame time and its interval
//   gpu_ms.<pass>...           each pass's median GPU time (empty: the pass did
//                              not run at that point); also gpu_ms.<pass>/shadow maps,
//                              the shadow maps drawn inside the pass that shades
//                              their light when shadows.reuse_map is on (the
//                              shadows pass then draws none: its time is ~0)
//   <counter>,<counter>.<pass>...
//                              only when counted: for each counter of PassCounts
//                              (fragments, samples, primitives, vertices, compute,
//                              bytes) the frame's (sum over its passes), then
//                              each pass's (not a span's: spans are not counted); exact, the same in every counted
//                              frame of a camera (an "all" row: the mean over
//                              the cameras); empty where not measured
//   pareto                     1 on the front of the point estimates, else 0
//   time                       what the front ranks by: frame, a pass, a span
//                              PASS/NAME or a sum of them (lighting+ao+ao_filter)
//   time_ms,time_ms_lo,time_ms_hi
//                              that time's median and 95% interval (a sum: the
//                              median of the per-frame sums, not a sum of medians)
//   front                      pareto | indistinguishable (off the front, not
//                              confidently dominated) | dominated (confidently
//                              dominated by a pareto point) | empty (no cost or error)
//   dominated_by               the pareto points that confidently dominate it ("2 3")
//   tied_with                  the other non-dominated points it cannot be told
//                              apart from, each with the axes: "1:error 3:both"
//   pick                       with a budget (BudgetPick): pick | tied (fits, not
//                              told apart from the pick in error) | fits | over; else empty
//   gpu_mem_peak_mib           the point's peak GPU memory over its counted frames,
//                              MiB (bytes / 2^20, exact; logical bytes, gl/MemoryLedger.h;
//                              an "all" row: the largest over the cameras); empty:
//                              not measured. A CSV written before it (ending at pick) still reads
// The front's cost axis is the time (time_ms) or, with --cost, a counter of
// the time's span (costOf; exact: only the error is tested). How the front
// and dominance are decided: ConfidentFront.h. A CSV written without the
// counters, or before the columns after pareto (ending at pareto), still
// reads, its missing fields empty.
// Numbers are written in the shortest form that reads back to the same double,
// so a table read back has the same front. Needs no GL.
#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "renderer/bench/ConfidentFront.h"
#include "renderer/graph/PassCounts.h"

namespace dw {

// A row's cost counters (PassCounts order); NaN: not measured. Whole numbers
// for one camera; the mean over the cameras in an "all" row.
using CounterValues = std::array<double, PassCounts::kCount>;

struct TradeoffRow {
    int point = 0;
    std::vector<std::string> axisValues;  // one per TradeoffTable::axes, as --set / --sweep take them
    std::string camera;
    std::string metric;
    std::string buffer;
    double error = 0.0, errorLo = 0.0, errorHi = 0.0;  // NaN: not measured
    int frames = 0;
    double frameGpuMs = 0.0, frameGpuMsLo = 0.0, frameGpuMsHi = 0.0;  // NaN: not measured
    std::vector<double> passGpuMs;  // one per TradeoffTable::passes; NaN: not run there
    CounterValues frameCounts;                // the frame's (sums over its passes)
    std::vector<CounterValues> passCounts;    // one per TradeoffTable::passes
    bool pareto = false;
    double timeMs = 0.0, timeMsLo = 0.0, timeMsHi = 0.0;  // TradeoffTable::time's; NaN: not measured
    std::string front;                                      // pareto | indistinguishable | dominated | ""
    std::vector<int> dominatedBy;                           // point numbers
    std::vector<std::pair<int, std::string>> tiedWith;      // point number, "time" | "error" | "both"
    std::string pick;                                       // pick | tied | fits | over | ""
    double gpuMemPeakMib = 0.0;                             // NaN: not measured
    // Not in the CSV: the points of its group it cannot be told apart from in
    // error, in time (dominated ones too; BudgetPick and frontSummary read them).
    std::vector<int> errorTies, timeTies;
    TradeoffRow();
};

class TradeoffTable {
public:
    static constexpr const char* kAllCameras = "all";

    std::vector<std::string> axes;    // the swept axes' names, in column order
    std::vector<std::string> passes;  // the passes of the gpu_ms.<pass> columns, in column order
    std::vector<TradeoffRow> rows;
    std::string time = "frame";  // what every row's time_ms is (the CSV's time column)
    // Not in the CSV: per camera, how the front was decided (ConfidentFront's rule line).
    std::map<std::string, std::string> frontRules;
    // Not in the CSV: per camera, the pairs tested on the cost axis (paired
    // draws), compared there by value (exact counters), and left untested.
    struct CostTests {
        int tested = 0, exact = 0, untested = 0;
        bool intervals = false;  // the intervals rule (no draws): compared, not tested
    };
    std::map<std::string, CostTests> frontCostTests;
    bool counted = false;             // the CSV carries the counter columns

    // The value of `axis` in a row ("" when the table has no such axis).
    std::string axisValue(const TradeoffRow& row, const std::string& axis) const;
    // A pass's median GPU ms in a row (NaN when not there).
    double passGpuMs(const TradeoffRow& row, const std::string& pass) const;

    // Whether a smaller value of `metric` is the better one: true for flip
    // and rms (errors), false for psnr and ssim (similarities).
    static bool lowerIsBetter(const std::string& metric);

    // Sets every row's `pareto`: the front of time against error, computed
    // (ParetoFront) separately within each group of rows with the same
    // camera, metric and buffer; the error is minimised, or maximised for
    // psnr and ssim. `time` is "frame" (frame_gpu_ms) or a pass whose
    // gpu_ms.<pass> column ranks instead (`tradeoff --time`: on llvmpipe the
    // frame time drowns a small pass's); a row where that pass did not run
    // has no time, so is off the front. Throws dw::Error when there are no
    // rows ("no points to compare: the sweep is empty") or the pass has no
    // column (the message lists the passes).
    // Also sets `front`, `dominated_by` and `tied_with` by the intervals rule
    // (ConfidentFront: no resamples here): rankBy(time), then markFront.
    // `time` may be a sum (a+b) only when the rows carry it (time == this->time).
    // `cost` (tradeoff --cost) is the front's cost axis: "gpu_ms" (the
    // default: the time, as above) or a counter of `time`'s span
    // (PassCounts::name: the frame's sum, that pass's, or the sum over the
    // passes of a+b); a counter has no noise: it is compared exactly
    // (FrontAxis::exact) and only the error is tested. Throws dw::Error for an
    // unknown cost, or a counter the table does not hold ("no point has
    // fragments counted").
    void markParetoFront(const std::string& time = "frame", const std::string& cost = "gpu_ms");
    // The time a front ranks by in a row: the carried time_ms when `time` is
    // the table's `time`, else frameGpuMs or passGpuMs(row, time).
    double timeOf(const TradeoffRow& row, const std::string& time) const;
    // Makes every row's time_ms (and interval) `time`'s and sets this->time:
    // frame from frame_gpu_ms, a pass from its median (no interval), the
    // carried one as it is. Throws Error for a pass without a column, or a
    // sum the rows do not carry (its interval needs the per-frame sums).
    void rankBy(const std::string& time);
    // The terms of a --time value: "frame", one pass (or PASS/NAME span), or a
    // sum a+b+c (each term named once). Throws Error for an empty term or one twice.
    static std::vector<std::string> timeTerms(const std::string& time);

    // The cost of a row on the front's cost axis (NaN: none): timeOf for
    // "gpu_ms", else the counter named `cost` of `time`'s span (a sum a+b:
    // the sum of the terms' counts; a span PASS/NAME has none).
    double costOf(const TradeoffRow& row, const std::string& time, const std::string& cost) const;
    // A counter of a pass in a row (NaN when not counted there).
    double passCount(const TradeoffRow& row, const std::string& pass, int counter) const;
    // Whether a gpu_ms.<pass> column also has counter columns: a pass, not a
    // span inside one ("lighting/shadow maps": spans are not counted).
    static bool hasCounterColumns(const std::string& pass) { return pass.find('/') == std::string::npos; }
    // Whether `cost` is gpu_ms or a counter's name.
    static bool isCost(const std::string& cost);
    static std::string costNames();  // "gpu_ms, fragments, samples, ..."
    // Whether any row has counter `counter` measured.
    bool hasCounter(int counter) const;
    // Throws dw::Error (one line, "--cost ...") unless `cost` is gpu_ms or a
    // counter some row holds.
    void checkCost(const std::string& cost) const;

    // The front decided per group (camera, metric, buffer) from each row's
    // evidence (the cost: whatever `evidence` says, time by default; the
    // error flipped for psnr/ssim by the caller: see intervalEvidence).
    using RowEvidence = std::function<FrontEvidence(size_t row)>;
    void markFront(const RowEvidence& evidence, FrontRule rule, double alpha = 0.05);
    // A row's cost and error with their intervals, both minimised (psnr and
    // ssim flipped): the cost is time_ms with its interval for "gpu_ms", else
    // the counter costOf(row, time, cost), exact.
    FrontEvidence intervalEvidence(const TradeoffRow& row, const std::string& cost = "gpu_ms") const;
    // Lines saying which points of `camera`'s rows cannot be told apart, per
    // axis ("error: points 0, 1, 2 and 3 cannot be told apart"), and which are dominated.
    // The cost axis is named `costName` ("time", or a counter's column:
    // "fragments", "fragments.ao"): a counter is said exact and compared by
    // value, a time with no paired draws (fewer than 6 rounds) not tested.
    std::vector<std::string> frontSummary(const std::string& camera, const std::string& costName = "time") const;

    std::vector<std::string> columns() const;
    static std::vector<std::string> columns(const std::vector<std::string>& axes, const std::vector<std::string>& passes,
                                            bool counted = false);
    std::string csv() const;
    // Reads csv() back. Throws FileError naming the file, the line and the
    // column of anything wrong: not this header, a column twice, a field that
    // is not a number where one belongs, a row of the wrong length, a point
    // with other axis values than its earlier rows, a row twice.
    static TradeoffTable parseCsv(const std::string& text, const std::string& path);
    static TradeoffTable readCsv(const std::string& path);
    // Writes csv() whole or not at all. Throws FileError.
    void writeCsv(const std::string& path) const;

    // Joins the tables of shards of one sweep (`names` name them in errors):
    // the same axes, no row (point, camera, metric, buffer) in two parts;
    // the passes are the union in order of first appearance. Rows sorted by
    // point, then camera (numbers in order, then "all"); the front recomputed.
    // Throws dw::Error naming the clash.
    static TradeoffTable merge(const std::vector<TradeoffTable>& parts, const std::vector<std::string>& names,
                               const std::string& time = "frame", const std::string& cost = "gpu_ms");
};

}  // namespace dw
