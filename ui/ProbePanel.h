#pragma once
// Pixel probe: every G-buffer value at the hovered (or pinned) pixel, decoded
// (normal, reconstructed position, depth, albedo, specular), the L-buffer,
// and the raw value of every other output produced this frame; with a
// magnifier around the pixel.
#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct ProbePanel {
    int zoomPixels = 15;  // magnifier width in image pixels
    void draw(const char* title, bool* open, UiState& state);
};

}  // namespace dw::ui
