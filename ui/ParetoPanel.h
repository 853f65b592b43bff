#pragma once
// The Pareto panel (issue 23, "In the workbench"): plots a tradeoff CSV
// (renderer/bench/TradeoffTable, what `deferred-workbench tradeoff --csv`
// writes) as median GPU frame ms against error, both with their intervals,
// one group of rows at a time (camera, metric, buffer), the Pareto front
// highlighted, joined and labelled; a click on a point applies its settings:
// each swept knob through the knob registry's checks, a "preset" axis as the
// Presets panel loads one, camera.near / camera.far on the camera. A value
// the registry refuses is named on screen and nothing is applied (the last
// good state is kept). Its quick sweep asks before it renders a value whose
// AOV frame is over the cost limit, and measures FLIP against the CPU
// reference of the view: with none shown it does not start, and offers to
// trace it first (as F9 does) or, as an explicit choice the plot then names,
// to measure against the current image (ParetoPanel::startSweep). The plot's
// axes are clamped to the data's sign: no negative time or error range.
// Across: the cost the `cost` combo names: gpu_ms, the table's time (time_ms:
// the frame, a pass or a sum of passes, as tradeoff --time ranked it), with
// its interval; or a counter the table holds (fragments, samples, primitives,
// vertices, compute, bytes of that time's span: TradeoffTable::costOf),
// exact, so with no interval across, the axis in the counter's unit. The
// combo starts at the CSV's own cost (marksCost: the one whose point-estimate
// front is the CSV's pareto column; the CSV does not name it). The marks are
// always the CSV's: with another cost chosen, a line says they were decided
// on the CSV's cost. The points are drawn by the CSV's `front`:
// on the front and told apart (filled), on the front but tied with another
// point (a ring), indistinguishable (a hollow square), dominated (small); the
// tooltip names dominated_by and tied_with. A budget (ms, above 0) marks the
// pick among the group's points (BudgetPicker: the least error whose time's
// 95% interval ends under it) with a green ring, and says the picker's lines;
// with a counter chosen, the budget is in that counter's unit and the pick
// BudgetPicker's counter form (tradeoff --cost C --budget N). A budget out
// of the CLI's range (OptionLimits' kBudgetMs / kBudget) is refused on screen
// with the CLI's message (BudgetPicker::check);
// *fit budget* beside it sweeps the speed/quality knobs about the current
// settings, applies the pick and measures it (FitBudgetView), its sweep then
// the table on show.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/bench/TradeoffTable.h"
#include "ui/AttributionView.h"
#include "ui/FitBudgetView.h"
#include "ui/UiState.h"

namespace dw::ui {

struct ParetoPanel {
    char path[512] = "tradeoff.csv";
    TradeoffTable table;
    std::string loadedPath;
    std::string error;        // the last load's or apply's error, shown under the controls
    std::string applied;      // what the last click applied
    int group = 0;            // which (camera, metric, buffer) group is plotted
    int hovered = -1;         // the row under the mouse (index into table.rows)
    std::string sweepKnob;    // the quick sweep's knob: the speed/quality knob last pointed at in Parameters
    bool sweepShown = true;   // the finished sweep's table is on show
    // The quick sweep's baseline, an explicit choice: false measures FLIP
    // against the CPU reference of the view (F9), true against the current
    // settings' image (where the current value scores 0; the plot says so).
    bool againstCurrent = false;
    // A sweep held back by its AOV cost: the knob, the whole message (as the
    // log has it), its first part (shown under *sweep anyway* and *cancel*)
    // and the estimate (wrapped below); empty when none is asked about.
    std::string askedKnob, askedCost, askedCostHeadline, askedCostDetail;
    // A sweep held back for want of a CPU reference (against the reference,
    // none shown): why, with *trace reference*, *use current image* and
    // *cancel*; askedConfirmed: its AOV question was answered.
    std::string askedReference;
    bool askedConfirmed = false;
    // A sweep waiting for the CPU reference it asked for: the knob (empty when
    // none), whether its AOV question was answered, UiState::referenceJobsEnded
    // when it asked.
    std::string waitingKnob;
    bool waitingConfirmed = false;
    std::uint64_t waitingJobsEnded = 0;
    // What the errors of the table on show are measured against (a quick
    // sweep's baseline; empty for a loaded CSV).
    std::string tableBaseline;
    AttributionView attribution;  // "Where the error comes from"
    FitBudgetView fit;            // the budget field's *fit budget*
    std::uint64_t fitShown = 0;   // FitBudgetRun::finished() of the fit whose table is on show (0: none)
    bool tableIsFit = false;      // the table on show is the last fit's sweep
    double fitBudgetMs = 0.0;     // the budget it was fitted to
    // Per axis, the value the points are labelled against (the fit's starting
    // settings: a label names only what differs); empty: every axis named.
    std::vector<std::string> labelCentre;
    // The budget field: 0 none; the pick's lines (or why none) for the group on show.
    double budgetMs = 0.0;
    double budgetCount = 0.0;  // the budget field with a counter cost: in that counter's unit
    std::vector<std::string> pickLines;
    // The plot's cost across: "gpu_ms" or a counter's name (PassCounts); and
    // the cost the table's front marks were decided on (marksCost at load).
    std::string cost = "gpu_ms";
    std::string csvCost = "gpu_ms";
    std::string pickedFor;  // the group and budget pickLines are for (recomputed when either changes)
    // The plot's ranges as last drawn: the cost across, error up (after padding
    // and clamping: never below 0 when the data are not).
    struct Axes {
        double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
    } plotAxes;

    // Starts a quick sweep of `knob` (UiState::sweep) against the CPU
    // reference of the view (ReferencePass's final image, at the frame's
    // size), or, with
    // againstCurrent, against the current image. Unless `confirmed`, a sweep
    // with a value whose AOV frame is over AovCostEstimate's limits at the
    // view's render size (the live view's guard, ui/AovCostGuard, for the
    // states a sweep renders) does not start: askedKnob / askedCost say why,
    // the Messages panel and the banner too, and false is returned. Against
    // the reference with none shown it does not start either: askedReference
    // says why (and the banner), and false is returned.
    bool startSweep(std::string knob, UiState& state, RenderSession& session, bool confirmed = false);
    // *trace reference*: asks for the CPU reference of the
    // view (UiState::requestReference, as F9) and starts the sweep of `knob`
    // when it is shown; a reference that does not come (cancelled, failed,
    // the view changed) ends the wait with a message.
    void traceReferenceThenSweep(std::string knob, UiState& state, bool confirmed);
    // Every frame (from draw): starts a waiting sweep once its reference is shown.
    void updateWaiting(UiState& state, RenderSession& session);
    // The values of a quick sweep of `knob` (QuickSweep::valuesOf) over the
    // current knobs whose AOV frame at w x h exceeds AovCostEstimate's
    // limits, each with the estimate's warning line.
    static std::vector<std::pair<std::string, std::string>> overAovCost(const std::string& knob, RenderSession& session,
                                                                        int width, int height);

    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
    // Reads `file`; on an error keeps the table loaded before and says why.
    bool load(const std::string& file);
    // The groups of rows the plot can show: "camera | metric | buffer".
    std::vector<std::string> groups() const;
    // The costs the plot can put across: gpu_ms, then each counter some row holds.
    std::vector<std::string> costs() const;
    // The cost a table's pareto column was decided on: the first of costs()
    // whose point-estimate front (TradeoffTable::markParetoFront on a copy)
    // marks the same rows; gpu_ms when none does (or gpu_ms does).
    static std::string marksCost(const TradeoffTable& t);
    // The rows' error and time ties and the front's rule (not in the CSV),
    // from the front decided again on csvCost, as tradeoff merge decides it;
    // the CSV's marks are kept. The budget's lines then say the ties as the CLI does.
    void tiesFromFront();
    // A row's cost across (NaN: none): time_ms for gpu_ms, else the counter.
    double costAcross(const TradeoffRow& r) const;
    // Applies row `row`'s settings; false (and `error` set) when any is refused.
    bool apply(int row, UiState& state, RenderSession& session);

    // The plot's box in screen pixels (left < right, top < bottom) and the
    // mapping of (GPU frame ms, error) over `axes` into it.
    struct PlotFrame {
        Axes axes;
        float left = 0, right = 0, top = 0, bottom = 0;
        float sx(double x) const { return static_cast<float>(left + (x - axes.xlo) / (axes.xhi - axes.xlo) * (right - left)); }
        float sy(double y) const { return static_cast<float>(bottom - (y - axes.ylo) / (axes.yhi - axes.ylo) * (bottom - top)); }
    };

private:
    // The pieces draw() draws, top to bottom.
    void pickSweepKnob(RenderSession& session);
    void sweepProgress(UiState& state);
    void referenceWait(UiState& state);
    void sweepControls(UiState& state, RenderSession& session);
    void askAboutCost(UiState& state, RenderSession& session);
    void askForReference(UiState& state, RenderSession& session);
    void showFinishedSweep(UiState& state);
    void showFinishedFit(UiState& state);
    void csvControls();
    void groupControls(const std::vector<std::string>& gs);
    void costControls();
    std::string acrossName() const;
    std::vector<int> groupRows(const std::string& groupName, std::string& metric);
    void plot(const std::vector<int>& rows, const std::string& metric, UiState& state, RenderSession& session);
    void plotAxesDrawn(const PlotFrame& f, float textX, const std::string& metric);
    void plotFront(const PlotFrame& f, const std::vector<int>& rows);
    void plotPoints(const PlotFrame& f, const std::vector<int>& rows, bool plotHovered);
    void budgetControls(const std::string& groupName);
    std::string hoverText(const TradeoffRow& r) const;
};

}  // namespace dw::ui
