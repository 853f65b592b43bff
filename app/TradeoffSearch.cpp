// deferred-workbench tradeoff --search --budget-ms X: coordinate descent over
// the speed/quality knobs to the least error under the budget
// (BudgetSearch); docs/tradeoffs.md, "Searching under a budget".
#include <cmath>
#include <cstdio>
#include <string>

#include "app/Commands.h"
#include "app/SweepOptions.h"
#include "headless/HeadlessGlContext.h"
#include "renderer/bench/BenchResults.h"
#include "renderer/record/HostInfo.h"
#include "renderer/study/BudgetSearch.h"
#include "renderer/study/TradeoffStudy.h"

namespace dw {

namespace {

std::string cell(double v, const char* format) {
    if (!std::isfinite(v)) return "-";
    char text[64];
    std::snprintf(text, sizeof(text), format, v);
    return text;
}

// One row per evaluation: its step, what proposed it, its error and time with their intervals, the step's pick column.
std::string evaluationTable(const TradeoffTable& t) {
    const std::string camera = BudgetPicker::shownCamera(t);
    const std::string metric = t.rows.empty() ? "error" : t.rows.front().metric + " (" + t.rows.front().buffer + ")";
    std::string out = "| evaluation | step | proposal | " + metric + " | 95% CI | " + t.time +
                      " GPU ms median | 95% CI | in its step |\n| ---: | ---: | --- | ---: | ---: | ---: | ---: | --- |\n";
    for (const auto& r : t.rows) {
        if (r.camera != camera) continue;
        out += "| " + std::to_string(r.point) + " | " + t.axisValue(r, "step") + " | " + t.axisValue(r, "proposal") +
               " | " + cell(r.error, "%.4g") + " | [" + cell(r.errorLo, "%.4g") + ", " + cell(r.errorHi, "%.4g") +
               "] | " + cell(r.timeMs, "%.3f") + " | [" + cell(r.timeMsLo, "%.3f") + ", " + cell(r.timeMsHi, "%.3f") +
               "] | " + r.pick + " |\n";
    }
    return out;
}

// The record: the search's table as the run's results, the walked knobs' grid and the search's settings.
ExperimentRecord searchRecord(const TradeoffStudyOptions& s, const TradeoffOptions& o, const TradeoffRunner& runner,
                              const BudgetSearchResult& found, const BenchFields& machine, const std::string& command) {
    TradeoffMeasurement m;
    m.result = BudgetSearch::asResult(found);
    m.machine = machine;
    return TradeoffStudy::record(s, o, runner, m, command);
}

}  // namespace

int runTradeoffSearch(const TradeoffStudyOptions& s, const TradeoffOptions& o, const SweepOptions& so,
                      const std::string& command) {
    BudgetSearchOptions bo;
    bo.base = o;
    bo.maxEvals = s.maxEvals;
    bo.aoRays = s.aoRays;
    bo.referencePixels = TradeoffStudy::referencePixels(s);
    TradeoffRunner start(o);  // the scene and every knob value checked before GL
    for (const auto& w : start.scene().warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    auto context = HeadlessGlContext::create();
    TradeoffStudyProgress progress;
    if (!so.quiet) progress.line = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    progress.warning = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    const BudgetSearchResult found = BudgetSearch::run(bo, progress);
    BenchFields machine = found.last.machine;
    machine.emplace_back("gl_platform", context->platform());
    machine.emplace_back("cpu", cpuModel());
    machine.emplace_back("compiler", compilerName());
    machine.emplace_back("date", utcNow());
    std::printf("## tradeoff --search: %s, %s of %s, budget %s, %d evaluation(s)\n\n"
                "Each row: an evaluation (point), the step that proposed it and what (start, the current settings "
                "again, or knob=value); the error with its tile-bootstrap 95%% interval; the median time with its "
                "95%% interval; in its step: the step's budget pick (pick | tied | fits | over).\n\n%s\n",
                start.scene().name.c_str(), o.metric.c_str(), o.buffer.c_str(),
                o.budget > 0.0 ? (cell(o.budget, "%.6g") + " " + o.cost).c_str() : (cell(o.budgetMs, "%.6g") + " ms").c_str(),
                found.evaluations, evaluationTable(found.table).c_str());
    for (const auto& l : found.lines) std::printf("%s\n", l.c_str());
    std::printf("\n");
    std::fflush(stdout);
    found.table.writeCsv(so.csv);
    writeBenchFile(so.json, searchRecord(s, o, start, found, machine, command).json(so.json), "tradeoff record");
    std::printf("wrote %s, %s\n", so.csv.c_str(), so.json.c_str());
    // No plot: the rows are evaluations of different steps, each with its own front and pick.
    return 0;
}

}  // namespace dw
