#pragma once
// The Pareto panel's "Where the error comes from" (issue 34 part 4):
// tradeoff --attribute for the view on show. Against the CPU reference of
// the view (F9; with none shown it offers to trace it first, as the quick
// sweep does), FLIP of the final image as the settings are, with every
// approximation family exact, and each family alone exact and alone left
// approximate (renderer/study/ErrorAttribution's AttributionRun, stepped one
// configuration a UI frame by the frame loop, before the view's own frame,
// with its knobs put back after each: the window stays responsive and the
// viewport never shows a row's settings). Shows progress and cancel, then a
// table of each family's two parts with their paired 95% intervals, bars
// with the intervals drawn (a part that cannot be told from 0 drawn faint),
// and how far the parts fail to add up. Errors are shown, never thrown.
#include <cstdint>
#include <string>

#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct AttributionView {
    std::string error;               // why the last attribution did not start or stopped
    bool waitingForReference = false;
    std::uint64_t waitingJobsEnded = 0;
    std::string viewKey;    // the view attributed: every knob, the camera, the size (viewKeyOf)
    std::string against;    // what it was measured against (the reference pass's description, the size)

    void draw(UiState& state, RenderSession& session);

private:
    bool start(UiState& state, RenderSession& session);
    void updateWaiting(UiState& state, RenderSession& session);
    void controls(UiState& state, RenderSession& session);
    static std::string viewKeyOf(RenderSession& session);
    void table(const AttributionResult& r, RenderSession& session) const;
    static void bars(const AttributionResult& r);
};

}  // namespace dw::ui
