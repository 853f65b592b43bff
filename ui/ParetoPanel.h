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
// AOV frame is over the cost limit (ParetoPanel::startSweep).
#include <string>
#include <utility>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/bench/TradeoffTable.h"
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
    // A sweep held back by its AOV cost: the knob and what the estimate says
    // (shown with *sweep anyway* and *cancel*); empty when none is asked about.
    std::string askedKnob, askedCost;

    // Starts a quick sweep of `knob` (UiState::sweep) against the CPU
    // reference of the view when one is shown, else the current image.
    // Unless `confirmed`, a sweep with a value whose AOV frame is over
    // AovCostEstimate's limits at the view's render size (the live view's
    // guard, ui/AovCostGuard, for the states a sweep renders) does not start:
    // askedKnob / askedCost say why, the Messages panel and the banner too,
    // and false is returned.
    bool startSweep(std::string knob, UiState& state, RenderSession& session, bool confirmed = false);
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
    // Applies row `row`'s settings; false (and `error` set) when any is refused.
    bool apply(int row, UiState& state, RenderSession& session);
};

}  // namespace dw::ui
