#pragma once
// Lights: list, select, switch on and off, move, colour, intensity,
// attenuation, cutoff and exponent; add and remove; animation. Shows each
// light's volume radius at the current threshold.
#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct LightsPanel {
    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
};

}  // namespace dw::ui
