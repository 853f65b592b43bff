#pragma once
// The workbench's CPU reference of the current view: started from the Render
// menu or F9, rendered in the background (renderer/reference/ReferenceJob)
// with its progress and a cancel button in the menu bar, then handed to the
// `reference` pass, whose outputs (reference.lbuffer, reference.final,
// reference.ao, compare.error) the inspector, probe and viewer show. When the
// view changes (camera, size, lights, a knob of the model) the reference is
// withdrawn and the pass says why.
#include <string>

#include "renderer/RenderSession.h"
#include "renderer/reference/ReferenceJob.h"
#include "ui/UiState.h"

namespace dw::ui {

struct ReferenceControls {
    // Menu items (inside the Render menu).
    void menuItems(UiState& state);
    // The progress bar and cancel button while a render runs (in the menu bar).
    void progressBar();
    // Every frame: takes a finished render, withdraws a stale one.
    void update(UiState& state, RenderSession& session);
    void start(UiState& state, RenderSession& session);

    int aoRays = 64;
    int pixelSamples = 1;  // reference --spp: samples per pixel

private:
    std::string currentKey(RenderSession& session, reference::ReferenceRequest* request = nullptr,
                           reference::ReferenceModel* model = nullptr) const;
    reference::ReferenceJob job_;
    std::string shownKey_;  // the view the reference pass shows ("" when none)
};

}  // namespace dw::ui
