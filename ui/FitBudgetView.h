#pragma once
// The Pareto panel's budget field and *fit budget* (issue 34 part 3, mission
// row 64): the least-error settings under a GPU-ms budget, from the sweep
// data, applied in one click, then measured.
//   1. *fit budget* sweeps the speed/quality knobs about the current settings
//      (FitBudgetRun: what `tradeoff --knobs speed/quality` sweeps, with the
//      time field as its --time), in the background with a progress bar and
//      *cancel* (a cancelled sweep leaves the settings as they were). FLIP is
//      measured against the CPU reference of the view (traced first, as F9,
//      when none is shown) or, chosen in the panel, the current image.
//   2. The pick (BudgetPicker: the least error whose time's 95% interval ends
//      under the budget) is applied through the knob registry and shown with
//      both intervals; when none fits it says so with the cheapest point's
//      time and applies nothing.
//   3. The change from the previous settings to the pick is then measured by
//      the cost of a change (ChangeMeasurement: the two sides in turns, one
//      frame a UI frame; the timings panel shows the same verdict), and the
//      time's verdict is shown with its interval. *undo* puts the previous
//      values of the changed knobs back (stopping the measurement).
// A budget of 0, below 0, NaN, infinite or above tradeoff --budget-ms's range
// (BudgetPicker::check, the CLI's message), or a time naming a pass the
// pipeline lacks, is refused with one line on screen (and in Messages)
// before anything renders. Errors are shown, never thrown.
#include <cstdint>
#include <optional>
#include <string>

#include "renderer/RenderSession.h"
#include "renderer/graph/ChangeCost.h"
#include "ui/UiState.h"

namespace dw::ui {

struct FitBudgetView {
    char time[128] = "frame";      // --time: frame, a pass or a sum a+b
    std::string message;           // why the last fit did not start, stopped, or applied nothing
    std::string referenceNote;     // against the reference: the effects on that it has not ("" none)
    std::string summary;           // what the last fit swept ("41 points ...; FLIP against ...")
    bool errorSaid = true;         // the running fit's stop (FitBudgetRun::error) is in `message`
    bool waitingForReference = false;
    std::uint64_t waitingJobsEnded = 0;
    std::uint64_t taken = 0;       // FitBudgetRun::finished() when its result was last taken
    std::vector<std::string> pickLines;  // the last fit's pick (or why none)
    std::string applied;           // what the last fit applied ("ssao.samples 16 -> 8")
    std::optional<KnobChange> change;    // the change applied: what *undo* reverses and the cost of a change measures
    bool measuring = false;        // the cost of `change` is being measured (UiState::measure)
    std::optional<ChangeVerdict> verdict;  // its verdict, kept (the timings panel may measure another change later)
    std::string measureStatus;     // "cancelled: ..." when the measurement stopped

    // `budgetMs` and `againstCurrent`: the Pareto panel's budget field and
    // baseline choice. Draws the budget field, *fit budget* and the time
    // field, then the running sweep or the last fit's result. `counter`
    // (the panel's cost, when a counter: "fragments", ...) and `budgetCount`:
    // the field then bounds that counter in its unit ("budget fragments"),
    // and *fit budget* (which fits GPU ms) is off, saying so.
    void draw(double& budgetMs, bool againstCurrent, UiState& state, RenderSession& session,
              const std::string& counter = "", double* budgetCount = nullptr);
    // Every frame (also while the panel is collapsed): a reference waited
    // for, a finished sweep's pick applied, the measurement followed.
    void update(double budgetMs, bool againstCurrent, UiState& state, RenderSession& session);
    // *fit budget*: false (and `message` set) when refused or waiting for the reference.
    bool start(double budgetMs, bool againstCurrent, UiState& state, RenderSession& session);
    // Applies the finished sweep's pick and starts measuring it (from update()).
    void takeResult(UiState& state, RenderSession& session);
    // *undo*: the changed knobs back to their previous values.
    void undo(UiState& state, RenderSession& session);

private:
    void controls(double& budgetMs, bool againstCurrent, UiState& state, RenderSession& session,
                  const std::string& counter, double* budgetCount);
    void progress(UiState& state);
    void result(UiState& state, RenderSession& session);
    void measuredChange(UiState& state, RenderSession& session);
    void followMeasurement(UiState& state);
};

}  // namespace dw::ui
