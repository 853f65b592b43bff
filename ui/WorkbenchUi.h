#pragma once
// The workbench window's UI: the menu bar, the panel layout (PanelLayout:
// columns and rows with draggable splitters, following the window), every
// panel, and the toast. Each panel is a small struct with draw(title, bool*
// open); which are open lives in UiState.
#include "renderer/RenderSession.h"
#include "ui/InspectorPanel.h"
#include "ui/KnobsPanel.h"
#include "ui/LightsPanel.h"
#include "ui/ParetoPanel.h"
#include "ui/PanelLayout.h"
#include "ui/PresetsPanel.h"
#include "ui/ProbePanel.h"
#include "ui/RecordDialog.h"
#include "ui/ReferenceControls.h"
#include "ui/ScenePanel.h"
#include "ui/TimingsPanel.h"
#include "ui/UiState.h"
#include "ui/ViewportPanel.h"

namespace dw::ui {

struct MessagesPanel {
    void draw(const char* title, bool* open, UiState& state);
};

// Where each open panel was drawn this frame, in window pixels: what the
// scripted mode reports (--layout-out) and the tests check.
struct DrawnPanel {
    std::string name;
    PanelRect rect;
};

class WorkbenchUi {
public:
    void draw(UiState& state, RenderSession& session, float dt);
    PanelLayout& layout() { return layout_; }
    // The panel's open flag in `flags`, by its window title; nullptr if none.
    static bool* panelFlag(PanelFlags& flags, const std::string& name);
    const std::vector<DrawnPanel>& drawnPanels() const { return drawn_; }
    ParetoPanel& pareto() { return pareto_; }

private:
    void menuBar(UiState& state, RenderSession& session);
    void splitters(const PanelLayout::Arrangement& a);
    void toast(const UiState& state);
    PanelLayout layout_;
    std::vector<DrawnPanel> drawn_;
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
    ParetoPanel pareto_;
    ReferenceControls reference_;
    RecordDialog record_;
};

}  // namespace dw::ui
