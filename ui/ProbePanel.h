#pragma once
// Pixel probe: every G-buffer value at the hovered (or pinned) pixel, decoded
// (normal, reconstructed position, depth, albedo, specular), the L-buffer,
// and the raw value of every other output produced this frame; with a
// magnifier around the pixel.
#include <string>

#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct ProbePanel {
    int zoomPixels = 15;  // magnifier width in image pixels
    // Every value the panel shows, as "label<TAB>value" lines: what *copy* puts on the clipboard.
    std::string copyText;
    void draw(const char* title, bool* open, UiState& state);
};

}  // namespace dw::ui
