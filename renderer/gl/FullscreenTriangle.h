#pragma once
// Draws shaders/fullscreen.vert's vertex-less triangle (core GL needs a VAO bound).
#include "renderer/gl/VertexArray.h"

namespace dw::gl {

class FullscreenTriangle {
public:
    void draw() const;

private:
    mutable VertexArray vao_;
};

// Restores the state every pass starts from: no blend, depth, stencil, cull,
// scissor or depth clamp; all colour channels writable; depth writes on;
// clip-space depth in [0, 1] (DepthConvention); stencil ALWAYS/KEEP, blend
// ONE/ZERO with FUNC_ADD, every sample-mask word all ones.
void resetPipelineState(int width, int height);

}  // namespace dw::gl
