#pragma once
// The workbench window's UI: the menu bar, the default arrangement of windows
// (Dear ImGui 1.86 has no docking), and every panel. Each panel is a small
// struct with draw(title, bool* open); which are open lives in UiState.
#include "renderer/RenderSession.h"
#include "ui/InspectorPanel.h"
#include "ui/KnobsPanel.h"
#include "ui/LightsPanel.h"
#include "ui/PresetsPanel.h"
#include "ui/ProbePanel.h"
#include "ui/ScenePanel.h"
#include "ui/TimingsPanel.h"
#include "ui/UiState.h"
#include "ui/ViewportPanel.h"

namespace dw::ui {

struct MessagesPanel {
    void draw(const char* title, bool* open, UiState& state);
};

class WorkbenchUi {
public:
    void draw(UiState& state, RenderSession& session, float dt);

private:
    void menuBar(UiState& state, RenderSession& session);
    void layout(UiState& state);
    std::vector<std::pair<const char*, glm::vec4>> layoutFor_;  // window -> x, y, w, h
    int layoutCond_ = 0;
    ViewportPanel viewport_;
    InspectorPanel inspector_;
    SideViewPanel side_;
    ProbePanel probe_;
    LightsPanel lights_;
    ScenePanel scene_;
    TimingsPanel timings_;
    KnobsPanel knobs_;
    PresetsPanel presets_;
    MessagesPanel messages_;
};

}  // namespace dw::ui
