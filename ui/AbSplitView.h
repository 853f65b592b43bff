#pragma once
// The viewport's A/B split as drawn (AbView holds its state; ViewportComposer
// makes its images): the controls row (A/B on, B's source, the display, Pin),
// the numbers row (A against B as `compare B A` states them, each side's
// error against the CPU reference, each side's GPU ms and the interval of
// their difference), and over the viewport image B's part right of a
// draggable vertical divider (B itself, or the heat map of |A - B| or FLIP).
#include <imgui.h>

#include "ui/UiState.h"

namespace dw::ui {

// The two rows, at the cursor. Returns the height in pixels the numbers took
// (0 while the split is off): they take room from the image box, not from the
// render size, so turning the split on keeps the frame (and a CPU reference
// of it) as it was.
float abControls(UiState& state);
// Over the image placed at `placed` in the box: B's part, the divider and its
// drag. Returns true while the divider has the mouse (the caller's camera and
// probe leave it alone). `hovered`: the viewport box is hovered.
bool drawAbSplit(UiState& state, ImVec2 boxMin, ImVec2 boxSize, const ImagePlacement& placed, bool hovered);

}  // namespace dw::ui
