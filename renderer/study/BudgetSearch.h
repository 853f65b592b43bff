#pragma once
// `tradeoff --search --budget-ms X` (or --budget N with a counter --cost):
// beyond a grid, a walk over the speed/quality knobs (the axes and values
// `--knobs speed/quality` names about the current settings) by coordinate
// descent, to the least error under the budget, bounded in evaluations.
//   A step: one knob. Its candidates are the values next to the current one
//     (a knob whose values are all numbers: the next smaller and the next
//     larger; after a move, the next one further the same way; a knob of
//     names, an enum: every other choice), measured in one TradeoffRunner run
//     with the current settings (re-measured, so time and error are compared
//     paired: interleaved rounds, the same tile resamples).
//   The move: BudgetPicker's pick over that run (the time's 95% interval ends
//     under the budget; the least error; the error ties by ConfidentFront's
//     paired bootstrap, familywise). It moves to the pick when the current
//     settings do not fit, or when they fit and the pick is told apart from
//     them in error (confidently better); a pick that cannot be told apart
//     from the current settings is not taken (the step says "could not
//     tell"). With nothing fitting it moves toward the budget: to the
//     cheapest candidate (median cost under the current one's) whose error
//     is no worse than the current value's (its estimate: the errors are
//     deterministic, the images' own); after a whole round
//     of knobs without a move and still nothing fitting, to the cheapest
//     whatever its error (relaxed).
//   It stops when every knob has been stepped once since the last move and
//     the settings fit (or the relaxed round moved nothing either):
//     converged; or when the next step would take it past max-evals.
// Every evaluation is a row of `table`: point = the evaluation's number (0,
// 1, ...), then the axes `step` (the step that proposed it, 1, 2, ...) and
// `proposal` ("start", "current", or knob=value), then each knob's value.
// Needs a current GL 4.5 context (the references through CachedReferences).
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/bench/BudgetPick.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/study/TradeoffStudy.h"

namespace dw {

struct BudgetSearchOptions {
    // The sweep of --knobs speed/quality about the current settings
    // (TradeoffStudy::runnerOptions), with budgetMs or budget (and cost) set.
    TradeoffOptions base;
    int maxEvals = 48;  // evaluations (points measured, re-measurements included); 1 .. 100000
    int aoRays = 64;
    std::uint32_t referenceSeed = 1;
    ReferencePixels referencePixels;  // --ref-spp, --ref-filter
};

struct BudgetSearchStep {
    int step = 0;                     // 1, 2, ...
    std::string knob;                 // the knob it varied
    std::vector<std::string> values;  // the candidates (not the current value)
    int firstEvaluation = 0, evaluations = 0;
    std::string outcome;              // "moved to ...", "stayed: ...", "could not tell: ..."
};

struct BudgetSearchResult {
    TradeoffTable table;                   // every evaluation, as above
    std::vector<BudgetSearchStep> steps;
    std::vector<std::string> knobs;        // the walked knobs, in step order
    std::vector<std::string> found;        // the final settings, one value per knob
    int foundEvaluation = -1;              // the evaluation that last measured them; -1: none measured
    bool fits = false;                     // the final settings fit the budget (their last measurement)
    bool converged = false;                // stopped because no knob moved, not at max-evals
    int evaluations = 0;
    size_t gridPoints = 0;                 // the points of --knobs speed/quality (one at a time) for comparison
    std::vector<std::string> lines;        // what tradeoff prints, each starting "search:"
    TradeoffResult last;                   // the last step's run (machine, shaders, settings)
    int referencesRendered = 0, referencesFromCache = 0;
};

class BudgetSearch {
public:
    // Throws dw::Error ("--max-evals ...") unless 1 <= n <= 100000.
    static void checkMaxEvals(int n);
    // Runs the search. Throws TradeoffCancelled when progress asks to stop;
    // dw::Error when the base options have no budget or no axes.
    static BudgetSearchResult run(const BudgetSearchOptions& options, const TradeoffStudyProgress& progress = {});
    // The search as a run's result, for its record: the last step's machine,
    // shaders and settings, the search's table, and the settings
    // search_evaluations, search_found_evaluation (replay compares against
    // them), search_found ("knob=value ...") and the references rendered.
    static TradeoffResult asResult(const BudgetSearchResult& found);
};

}  // namespace dw
