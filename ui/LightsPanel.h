#pragma once
// Lights: list, select, switch on and off, move, colour, intensity,
// attenuation, cutoff and exponent; add and remove; animation. Shows each
// light's volume radius at the current threshold.
#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct LightsPanel {
    bool scrollToSelected = false;  // a light was just added: bring its row into view
    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
};

}  // namespace dw::ui
