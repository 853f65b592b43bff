#pragma once
// The viewport: the final image or any named output, overlays, the camera's
// mouse controls (orbit: left drag rotates, middle drag pans, wheel zooms;
// fly: right drag looks, wheel moves), hover to probe a pixel and click to pin
// it, and the newest error as a banner.
#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct ViewportPanel {
    bool dragging = false;
    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
};

// Keyboard: arrows and +/- orbit and zoom (seed 001 3.4); WASD/QE fly while the
// right button is held (seed 004); a axes, d deferred, t textured, w wireframe,
// v light volumes, f orbit/fly, l animate lights, F5 reload shaders,
// F12 screenshot, Esc unpin the probe.
void handleShortcuts(UiState& state, RenderSession& session, float dt);
// The key list for the Help window.
const char* shortcutHelp();

}  // namespace dw::ui
