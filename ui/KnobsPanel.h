#pragma once
// Parameter panel generated from the knob registry: one group per pass, one
// widget per knob by its type, a reset per knob and per group. No knob is
// written here by name.
#include "renderer/knobs/KnobRegistry.h"

namespace dw::ui {

struct KnobsPanel {
    char filter[64] = {};
    void draw(const char* title, bool* open, KnobRegistry& knobs);
};

// One knob's row (name, widget, reset) inside a 3-column ImGui table.
// Returns true when the value changed.
bool knobWidget(KnobRegistry& knobs, int id);

}  // namespace dw::ui
