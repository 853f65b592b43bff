#pragma once
// The A/B view's images (issue 23, "In the workbench"): the current settings'
// final image (A) and the other side's (B: a pinned snapshot, a preset's
// render, or the CPU reference's final image), as textures the viewport shows
// left and right of a divider; their comparison with B as the reference
// (ImageComparison::measure, LDR: exactly what `compare B.png A.png` prints
// for the same two images); and a heat map of their per-pixel difference
// (the mean |A - B| over the colour channels, scaled 0 to its maximum) or of
// FLIP's map (0 to 1), through HeatMap's Turbo colours.
// Reads FloatImages of display values in [0, 1], rows top-down (what
// RenderSession::readRaw("final") gives); writes RGBA8 textures stored
// bottom-up, as the pipeline's outputs are, so a viewer draws them alike.
// Errors: Error naming both shapes when A and B differ in shape.
#include "renderer/gl/Texture.h"
#include "renderer/io/ImageIO.h"
#include "renderer/metrics/ImageComparison.h"

namespace dw {

class SplitComparison {
public:
    enum class Map { Difference, Flip };

    // Uploads both sides and measures them (FLIP included: a few hundred ms
    // on a CPU at 640x360; call it when an image changed, not every frame).
    void set(const FloatImage& a, const FloatImage& b);
    // The heat map of the last set() pair.
    void makeHeatMap(Map map);

    bool ready() const { return ready_; }
    const FloatImage& imageA() const { return a_; }
    const FloatImage& imageB() const { return b_; }
    const gl::Texture& textureA() const { return textureA_; }
    const gl::Texture& textureB() const { return textureB_; }
    const gl::Texture& heatMap() const { return heat_; }
    // The heat map's scale: 0 to this (the largest mean |A - B|, or 1 for FLIP).
    double heatHigh() const { return heatHigh_; }
    // B as the reference, A as the test.
    const ImageComparison& comparison() const { return comparison_; }

private:
    static void upload(gl::Texture& texture, const FloatImage& image);
    FloatImage a_, b_;
    gl::Texture textureA_, textureB_, heat_;
    ImageComparison comparison_;
    double heatHigh_ = 1.0;
    bool ready_ = false;
};

}  // namespace dw
