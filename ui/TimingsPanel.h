#pragma once
// Live GPU timer graphs: per-pass milliseconds from the timestamp ring over
// the last few hundred frames, stacked to the frame total, with min / mean /
// max / median over the window, the CPU frame time beside it, pause, and
// export of the captured window to CSV.
#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct TimingsPanel {
    int window = 300;
    bool stacked = true;
    char csvPath[256] = "timings.csv";
    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
};

// A stable, distinct colour per pass name.
unsigned passColor(const std::string& name);

}  // namespace dw::ui
