// Camera uniforms (dw::CameraUniforms) and position reconstruction from depth
// (seed 000, section 3.1: window coordinates and depth back through the
// inverse projection give the view-space position).
#include "bindings.glsl"

layout(std140, binding = CAMERA_UBO) uniform CameraBlock {
    mat4 view;
    mat4 projection;
    mat4 viewProjection;
    mat4 inverseProjection;
    mat4 inverseView;
    vec4 viewport;  // width, height, 1/width, 1/height
    vec4 clip;      // near, far, tan(fovY/2), aspect
} camera;

// uv in [0,1]^2 (pixel centres), depth in [0,1] -> view-space position.
vec3 viewPositionFromDepth(vec2 uv, float depth) {
    vec4 ndc = vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec4 v = camera.inverseProjection * ndc;
    return v.xyz / v.w;
}

vec3 viewPositionAtPixel(ivec2 px, float depth) {
    return viewPositionFromDepth((vec2(px) + 0.5) * camera.viewport.zw, depth);
}

// Distance along -Z in view space for a window depth (perspective projection).
float linearizeDepth(float depth, float near, float far) {
    float z = depth * 2.0 - 1.0;
    return 2.0 * near * far / (far + near - z * (far - near));
}
