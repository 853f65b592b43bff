#pragma once
// The Pareto panel (issue 23, "In the workbench"): plots a tradeoff CSV
// (renderer/bench/TradeoffTable, what `deferred-workbench tradeoff --csv`
// writes) as median GPU frame ms against error, both with their intervals,
// one group of rows at a time (camera, metric, buffer), the Pareto front
// highlighted, joined and labelled; a click on a point applies its settings:
// each swept knob through the knob registry's checks, a "preset" axis as the
// Presets panel loads one, camera.near / camera.far on the camera. A value
// the registry refuses is named on screen and nothing is applied (the last
// good state is kept).
#include <string>
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

    // Starts a quick sweep of `knob` (UiState::sweep) against the CPU
    // reference of the view when one is shown, else the current image.
    bool startSweep(const std::string& knob, UiState& state, RenderSession& session);

    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
    // Reads `file`; on an error keeps the table loaded before and says why.
    bool load(const std::string& file);
    // The groups of rows the plot can show: "camera | metric | buffer".
    std::vector<std::string> groups() const;
    // Applies row `row`'s settings; false (and `error` set) when any is refused.
    bool apply(int row, UiState& state, RenderSession& session);
};

}  // namespace dw::ui
