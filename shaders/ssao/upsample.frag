#version 450 core
// Depth-aware upsampling of a reduced-resolution AO buffer to full
// resolution: the four nearest AO texels, weighted bilinearly and by
// 1 / (delta + |z_full - z_ao|), so occlusion does not bleed across depth edges.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../params/ssao_blur.h"

layout(binding = AO_FILTER_SOURCE_TEXTURE) uniform sampler2D uAo;
layout(binding = AO_FILTER_DEPTH_TEXTURE) uniform sampler2D uDepth;

out float outOcclusion;

float linearDepth(ivec2 px) {
    float d = texelFetch(uDepth, px, 0).r;
    return isFarDepth(d) ? 1e30 : -viewPositionAtPixel(px, d).z;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec2 aoSize = vec2(blur.aoSize);
    vec2 pos = (vec2(px) + 0.5) / camera.viewport.xy * aoSize - 0.5;
    ivec2 base = ivec2(floor(pos));
    vec2 f = pos - vec2(base);
    float z = linearDepth(px);
    float sum = 0.0, weights = 0.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ivec2 q = clamp(base + ivec2(i, j), ivec2(0), blur.aoSize - 1);
            float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) + 1e-4;
            if (blur.mode == SSAO_BLUR_MODE_BILATERAL) {
                ivec2 qFull = ivec2((vec2(q) + 0.5) / aoSize * camera.viewport.xy);
                w *= 1.0 / (blur.delta + abs(z - linearDepth(qFull)));
            }
            sum += w * texelFetch(uAo, q, 0).r;
            weights += w;
        }
    // Clamped here, after the blur: a method whose per-pixel estimate is
    // unbiased only on average (GTAO's slices) leaves values above 1 in ao.raw.
    outOcclusion = clamp(sum / weights, 0.0, 1.0);
}
