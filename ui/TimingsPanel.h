#pragma once
// Live GPU timer graphs: per-pass milliseconds from the timestamp ring over
// the last few hundred frames, stacked to the frame total or as lines, on a
// linear or log axis with ticks, with a hover readout (frame, pass, ms) and
// passes shown, hidden or isolated from the table; min / mean / max / median
// over the window; the pass's own CPU time when isolated CPU timing is on;
// the cost of the last committed knob change per pass, measured on demand
// (ChangeCost: frames of the values before and after, interleaved, one a UI
// frame, with a progress bar and cancel; medians, the difference and a
// Bonferroni-adjusted bootstrap interval of the ratio, passes the change
// cannot reach never flagged); pause and CSV export. The history starts over when the scene or the render size
// changes, so statistics never mix two configurations.
#include <nlohmann/json.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "renderer/bench/ChangeMeasurement.h"
#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct TimingsPanel {
    int window = 300;
    bool stacked = true;
    bool logScale = false;
    char csvPath[256] = "timings.csv";
    std::set<std::string> hidden;  // passes not drawn in the graph
    std::string solo;              // when set, the only pass drawn
    // The last committed knob change (what *measure* measures) and its settings.
    KnobChangeWatcher watcher;
    std::optional<KnobChange> change;
    ChangeMeasurement::Settings measureSettings;
    std::uint64_t configSeen = ~0ull;  // UiState::configSince when last looked at
    std::uint64_t putBackSeen = 0;     // UiState::knobsPutBack when last looked at
    std::string sceneSource;

    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
    // Starts measuring `change` (UiState::measure; the frame loop renders its frames).
    void startMeasure(UiState& state, RenderSession& session);

private:
    void watchForChanges(UiState& state, RenderSession& session);
    void toolbar(UiState& state, PassTimer& timer, RenderSession& session);
    void graph(UiState& state, PassTimer& timer, const std::vector<std::string>& passes);
    // The hover text of a pass's name carries its statistics line (`report`).
    void table(PassTimer& timer, const std::vector<std::string>& passes, const FrameReport& report);
    void changeBar(UiState& state, RenderSession& session);   // the change, measure / progress and cancel
    void changeCost(UiState& state, RenderSession& session);  // the verdict
    void changeCostLines(const ChangeVerdict& v);              // the verdict in a panel too narrow for its table
};

// A stable, distinct colour per pass name.
unsigned passColor(const std::string& name);
// Axis ticks: "nice" values (1, 2, 5 x 10^k) from 0 to `top` (linear), or
// from `bottom` to `top` on a log axis: the powers of ten, with 2 and 5 times
// them when the range spans two decades or less, and the range's own ends
// when fewer than two of those fall inside. At most about `count` of them.
std::vector<float> axisTicks(float bottom, float top, bool logScale, int count = 5);
// The top bar's GPU time, always of the latest rendered frame: "GPU 12.34 ms"
// once its timer results are in; before that the newest timed frame of this
// configuration with its index, "GPU 11.90 ms (frame 41; 43 pending)", or
// "GPU ... ms (frame 43 pending)" when there is none.
std::string gpuFrameText(const PassTimer& timer, const UiState& state);
// What --layout-out reports of the timings: the top bar's text, the latest
// rendered and timed frames (with their cost counters while *counters* is
// on: "counting"), and the cost of the change (its state, knobs, frames and
// the verdict per pass).
nlohmann::json timingsReport(const PassTimer& timer, const UiState& state);

}  // namespace dw::ui
