// The camera block (declared in shaders/params/camera.h; dw::CameraUniforms)
// and position reconstruction from depth (seed 000, section 3.1: window
// coordinates and depth back through the inverse projection give the
// view-space position). Clip-space depth is in
// [0, 1] (glClipControl GL_ZERO_TO_ONE), so window depth is NDC z; depth.x
// says whether the mapping is reversed (near 1, far 0; dw::DepthConvention).
#include "../params/camera.h"

bool depthReversed() { return camera.depth.x > 0.5; }
// Window depth of the far plane (the clear value) and of the near plane.
float farPlaneDepth() { return camera.depth.y; }
float nearPlaneDepth() { return camera.depth.z; }
// Whether a stored depth is the cleared background (nothing was drawn).
bool isFarDepth(float depth) { return depthReversed() ? depth <= 0.0 : depth >= 1.0; }

// uv in [0,1]^2 (pixel centres), depth in [0,1] -> view-space position.
vec3 viewPositionFromDepth(vec2 uv, float depth) {
    vec4 ndc = vec4(uv * 2.0 - 1.0, depth, 1.0);
    vec4 v = camera.inverseProjection * ndc;
    return v.xyz / v.w;
}

vec3 viewPositionAtPixel(ivec2 px, float depth) {
    return viewPositionFromDepth((vec2(px) + 0.5) * camera.viewport.zw, depth);
}

// Window depth of a point `dist` along the axis of a perspective projection
// with planes near, far, in this frame's convention (DepthConvention::perspectiveDepth).
float perspectiveDepth(float dist, float near, float far) {
    return depthReversed() ? near * (far - dist) / (dist * (far - near)) : far * (dist - near) / (dist * (far - near));
}
