#pragma once
// gui --layout-out: the window as the last frame left it, as JSON, for the
// tests and scripts to check: where ImGui drew each panel (its own record,
// not ours) and each named item (ui::noteItem), the window and framebuffer
// sizes in pixels, the probe, the camera, the viewport's output and render
// size, the CPU reference and its errors, the A/B split's numbers, the
// timings, and the error messages. Written by GuiLoop after the last scripted
// frame, or as the window closes. Throws dw::FileError when the file cannot
// be written (writeFileAtomically).
#include <string>

#include "renderer/RenderSession.h"
#include "ui/UiState.h"
#include "ui/WorkbenchUi.h"

namespace dw {

// Call between ImGui::NewFrame and the next (it reads ImGui's windows).
// `fbw` x `fbh`: the window's framebuffer in pixels.
void writeLayoutReport(const std::string& path, const ui::WorkbenchUi& ui, const ui::UiState& state, int fbw, int fbh,
                       RenderSession& session);

}  // namespace dw
