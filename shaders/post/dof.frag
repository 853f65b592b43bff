#version 450 core
// Depth of field (seed 004 "Depth of Field", with the focal distance its
// "moving forward" section asks for): a circle of confusion from view depth,
// zero within focus_range around focus_distance and growing to max_radius one
// focus_range beyond it, for the far field and (optionally) the near field;
// then a gather over a golden-angle disc. A sample counts when its own blur
// reaches the centre (near-field objects spread over what is behind them) or,
// for samples farther than the centre, when the centre's blur reaches it (so
// sharp foreground does not smear into a blurred background).
// The image is the tone mapper's 8-bit output; with values.w set it is
// sRGB-encoded, and the gather averages linear light, then re-encodes.
#include "../common/camera.glsl"
#include "../common/color.glsl"

layout(binding = 0) uniform sampler2D uImage;
layout(binding = 1) uniform sampler2D uDepth;

layout(std140, binding = PASS_UBO) uniform DofParams {
    ivec4 modes;   // x near blur, y far blur, z samples, w write the CoC only
    vec4 values;   // x focus distance, y focus range, z max radius (px), w input is sRGB-encoded
} dof;

layout(location = 0) out vec4 outColor;

float linearDepth(ivec2 px) {
    float d = texelFetch(uDepth, px, 0).r;
    return d >= 1.0 ? camera.clip.y : -viewPositionAtPixel(px, d).z;
}

// Signed circle of confusion in pixels: negative in front of the focus.
float coc(float z) {
    float d = z - dof.values.x;
    float halfRange = 0.5 * dof.values.y;
    float t = clamp((abs(d) - halfRange) / max(dof.values.y, 1e-3), 0.0, 1.0);
    if (d < 0.0 && dof.modes.x == 0) return 0.0;
    if (d > 0.0 && dof.modes.y == 0) return 0.0;
    return sign(d) * t * dof.values.z;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uImage, 0);
    float zc = linearDepth(px);
    float cc = coc(zc);
    if (dof.modes.w != 0) {
        outColor = vec4(cc, 0.0, 0.0, 1.0);
        return;
    }
    bool srgb = dof.values.w != 0.0;
    vec3 center = texelFetch(uImage, px, 0).rgb;
    if (srgb) center = srgbToLinear(center);
    int n = dof.modes.z;
    float maxR = dof.values.z;
    vec3 sum = center;
    float weights = 1.0;
    const float golden = 2.39996323;
    for (int i = 1; i < n; ++i) {
        float r = maxR * sqrt(float(i) / float(n));
        float a = float(i) * golden;
        ivec2 q = clamp(px + ivec2(round(r * vec2(cos(a), sin(a)))), ivec2(0), size - 1);
        float zq = linearDepth(q);
        float cq = coc(zq);
        float reach = zq < zc ? abs(cq) : min(abs(cq), abs(cc));
        float w = clamp(reach - r + 1.0, 0.0, 1.0);
        vec3 c = texelFetch(uImage, q, 0).rgb;
        sum += (srgb ? srgbToLinear(c) : c) * w;
        weights += w;
    }
    vec3 result = sum / weights;
    outColor = vec4(srgb ? linearToSrgb(result) : result, 1.0);
}
