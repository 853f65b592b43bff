#pragma once
// The pixels near a shadow's edge, for studies whose error lives there
// (shadow map size, PCF radius: `tradeoff --mask shadow_edges`; issue 23).
//
// Reads the reference's shadow buffer (ReferenceImages::shadow, `--buffer
// shadow`): width x height x 1, the fraction of the shadow-casting lights'
// light reaching each pixel, 1 lit, 0 shadowed, rows top-down.
// An edge pixel is one whose 3x3 neighbourhood (clamped at the image border)
// holds both a lit and a shadowed value: max - min over it > `contrast`
// (default 0.1, so several lights' partial shadows count, and the smooth
// variation of one light's share across a surface does not). The mask is the
// edge pixels dilated by `dilation` pixels (a square, Chebyshev distance;
// default 2: "within 2 px of an edge").
// Output: width x height x 1, 1 inside the mask, 0 outside.
// Errors: Error when the shadow image is not one channel or is empty.
#include "renderer/io/ImageIO.h"

namespace dw {

struct ShadowEdgeSettings {
    double contrast = 0.1;
    int dilation = 2;
};

class ShadowEdgeMask {
public:
    static FloatImage fromShadow(const FloatImage& shadow, const ShadowEdgeSettings& settings = {});
    // The number of pixels inside a mask (value > 0.5).
    static long long count(const FloatImage& mask);
};

}  // namespace dw
