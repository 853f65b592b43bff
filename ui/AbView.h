#pragma once
// The viewport's A/B split (issue 23, "In the workbench"): the current
// settings (A, left of a draggable vertical divider) against a pinned
// snapshot, a preset rendered over the current settings, or the CPU reference
// (B, right of it); shown split, or with B's side as the heat map of |A - B|
// or of FLIP; both sides' error against the reference when there is one,
// their GPU frame times, and the interval of the difference of the medians.
// The settings are the viewport panel's; ViewportComposer fills the rest.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/metrics/Bootstrap.h"

namespace dw::ui {

enum class AbSource { Pinned, Preset, Reference };
enum class AbDisplay { Split, Difference, Flip };

struct AbSide {
    // Against the CPU reference's final image (when one is shown): RMS and FLIP mean.
    bool haveError = false;
    double rms = 0.0, flip = 0.0;
    std::vector<double> gpuMs;  // frame times (GPU ms) of this side's frames since the view changed
};

struct AbView {
    bool enabled = false;
    AbSource source = AbSource::Pinned;
    AbDisplay display = AbDisplay::Split;
    float divider = 0.5f;      // of the image's width, from its left edge
    bool dragging = false;     // the divider is being dragged (the camera keeps still)
    std::string preset;        // AbSource::Preset: a built-in preset's name or a preset file
    bool pinRequest = false;   // "Pin": the current image becomes B (AbSource::Pinned)
    unsigned generation = 0;   // bumped by every settings change that needs new images

    // Filled by ViewportComposer.
    bool ready = false;                          // both images and the comparison are there
    unsigned textureA = 0, textureB = 0, heatTexture = 0;
    int width = 0, height = 0;
    std::string unavailable;                     // why there is no B (no pin yet, no reference, a bad preset)
    std::string describeB;                       // "pinned (frame 12)", "preset SSAO1", "CPU reference"
    double heatHigh = 1.0;                       // the heat map's scale: 0 to this
    // B as the reference, A as the test: what `compare B.png A.png` prints.
    double rms = 0.0, psnr = 0.0, meanAbsolute = 0.0, flip = 0.0;
    bool haveFlip = false;
    AbSide a, b;
    DifferenceInterval gpuDifference;            // median(A) - median(B), GPU ms
    glm::vec2 dividerScreen{0.0f};               // where the divider was drawn (x, top y)
};

}  // namespace dw::ui
