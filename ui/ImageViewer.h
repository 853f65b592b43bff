#pragma once
// The texture viewer shared by the viewport and the side view (RenderDoc's
// texture viewer is the model): controls above the image (layer / sample,
// channel, mapping, exposure or value range, zoom, histogram), a colour bar
// with values for heat maps and remapped ranges, a histogram of the shown
// buffer's raw values per channel with log counts and the range's two
// handles on it, and the image itself with zoom to pixel level (Ctrl+wheel,
// at the cursor; nearest-neighbour sampling when a pixel covers several
// screen pixels) and pan (Ctrl+left drag). Settings are kept per output
// (ImageView).
#include <imgui.h>

#include "renderer/graph/OutputRegistry.h"
#include "ui/UiState.h"

namespace dw::ui {

// The controls; `output` may be null (the final image: only zoom). Returns
// whether a display setting changed.
// With a `prefix`, the save buttons are noted (noteItem) as
// "<prefix>.save_exr" and "<prefix>.save_png".
bool imageViewControls(ImageView& view, const PublishedOutput* output, const ShownImage& img, const std::string& prefix = "");
// The colour bar and, when the view asks for it, the histogram, full width at the cursor.
void imageViewLegend(ImageView& view, const PublishedOutput* output, const ShownImage& img);
// Draws `img` in the box by the view's zoom and pan, clipped to the box, and
// takes Ctrl+wheel / Ctrl+drag when `hovered` / `active` (the caller's item
// over the box). Returns where the image lies, for probing.
ImagePlacement drawImageView(ImageView& view, const ShownImage& img, ImVec2 boxMin, ImVec2 boxSize, const gl::Sampler* nearest,
                             bool hovered, bool active);

// The value range a colour bar and the histogram handles show for `view`
// (the manual range, or the automatic one the last render found); false
// when the mapping has no range (normals, tone map, display-ready outputs).
bool displayRange(const ImageView& view, const PublishedOutput& output, const ShownImage& img, float& lo, float& hi);

}  // namespace dw::ui
