#pragma once
// Live GPU timer graphs: per-pass milliseconds from the timestamp ring over
// the last few hundred frames, stacked to the frame total or as lines, on a
// linear or log axis with ticks, with a hover readout (frame, pass, ms) and
// passes shown, hidden or isolated from the table; min / mean / max / median
// over the window; the pass's own CPU time when isolated CPU timing is on;
// the cost of the last knob change per pass (ChangeCost: medians before and
// after, the difference and a bootstrap interval of the ratio); pause and CSV
// export. The history starts over when the scene or the render size
// changes, so statistics never mix two configurations.
#include <set>
#include <string>
#include <vector>

#include "renderer/graph/ChangeCost.h"
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
    ChangeCost cost;
    // The costs as last computed (a bootstrap per pass): again only when new frames were timed.
    std::vector<PassChangeCost> costs;
    std::uint64_t costsAtFrame = ~0ull;
    std::uint64_t firstUsableFrame = 0;  // after a reset: the first frames (shader compiles) are no baseline
    std::vector<double> knobValues;  // to name the knob that changed
    std::uint64_t knobGeneration = ~0ull;
    std::string sceneSource;
    glm::ivec2 renderSize{0, 0};

    void draw(const char* title, bool* open, UiState& state, RenderSession& session);

private:
    void watchForChanges(UiState& state, RenderSession& session);
    void graph(UiState& state, PassTimer& timer, const std::vector<std::string>& passes);
    void table(PassTimer& timer, const std::vector<std::string>& passes);
    void changeCost(PassTimer& timer);
};

// A stable, distinct colour per pass name.
unsigned passColor(const std::string& name);
// Axis ticks: "nice" values (1, 2, 5 x 10^k) from 0 to `top` (linear), or the
// powers of ten from `bottom` to `top` (log). At most about `count` of them.
std::vector<float> axisTicks(float bottom, float top, bool logScale, int count = 5);

}  // namespace dw::ui
