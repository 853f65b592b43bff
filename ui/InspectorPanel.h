#pragma once
// Pass inspector: the passes of this frame, ran or skipped (and why), their
// GPU time and outputs. Any output can be shown in the viewport or the side
// view, with channel, range, depth linearisation, normal colours, heat map and
// exposure controls. Built from the pipeline's output registry, with no
// per-pass code.
#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct InspectorPanel {
    std::vector<std::string> listed;  // the outputs the last draw listed, in order
    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
};

// The side view: a second output beside the viewport.
struct SideViewPanel {
    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
};


}  // namespace dw::ui
