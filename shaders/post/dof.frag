#version 450 core
// Depth of field (seed 004 "Depth of Field", with the focal distance its
// "moving forward" section asks for): a circle of confusion from view depth,
// zero within focus_range around focus_distance and growing to max_radius one
// focus_range beyond it, for the far field and (optionally) the near field;
// then a gather over a golden-angle disc. A sample counts when its own blur
// reaches the centre (near-field objects spread over what is behind them) or,
// for samples farther than the centre, when the centre's blur reaches it (so
// sharp foreground does not smear into a blurred background).
// The image is the tone mapper's 8-bit output; with srgbInput set it is
// sRGB-encoded, and the gather averages linear light, then re-encodes.
#include "../common/camera.glsl"
#include "../common/color.glsl"
#include "../params/dof.h"

layout(binding = 0) uniform sampler2D uImage;
layout(binding = 1) uniform sampler2D uDepth;

layout(location = 0) out vec4 outColor;

float linearDepth(ivec2 px) {
    float d = texelFetch(uDepth, px, 0).r;
    return isFarDepth(d) ? camera.clip.y : -viewPositionAtPixel(px, d).z;
}

// Signed circle of confusion in pixels: negative in front of the focus.
float coc(float z) {
    float d = z - dof.focusDistance;
    float halfRange = 0.5 * dof.focusRange;
    float t = clamp((abs(d) - halfRange) / max(dof.focusRange, 1e-3), 0.0, 1.0);
    if (d < 0.0 && dof.nearBlur == 0) return 0.0;
    if (d > 0.0 && dof.farBlur == 0) return 0.0;
    return sign(d) * t * dof.maxRadius;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uImage, 0);
    float zc = linearDepth(px);
    float cc = coc(zc);
    if (dof.cocOnly != 0) {
        outColor = vec4(cc, 0.0, 0.0, 1.0);
        return;
    }
    bool srgb = dof.srgbInput != 0;
    vec3 center = texelFetch(uImage, px, 0).rgb;
    if (srgb) center = srgbToLinear(center);
    int n = dof.sampleCount;
    float maxR = dof.maxRadius;
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
