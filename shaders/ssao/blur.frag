#version 450 core
// Separable blur of the AO buffer (seed 000 section 4.6.3, seed 002 section
// 5.2). Gaussian weights, multiplied in the cross-bilateral mode by
// w = 1 / (delta + |d_center - d_current|) on linear depth (eq. 4.7), and
// renormalised so the weights sum to 1. One direction per draw.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../params/ssao_blur.h"

layout(binding = AO_FILTER_SOURCE_TEXTURE) uniform sampler2D uAo;
layout(binding = AO_FILTER_DEPTH_TEXTURE) uniform sampler2D uDepth;

out float outOcclusion;

float linearDepthAt(ivec2 aoPixel) {
    vec2 uv = (vec2(aoPixel) + 0.5) / vec2(blur.aoSize);
    ivec2 px = ivec2(uv * camera.viewport.xy);
    float d = texelFetch(uDepth, px, 0).r;
    return isFarDepth(d) ? 1e30 : -viewPositionAtPixel(px, d).z;
}

void main() {
    ivec2 c = ivec2(gl_FragCoord.xy);
    ivec2 dir = blur.direction;
    float zc = linearDepthAt(c);
    float sum = 0.0, weights = 0.0;
    for (int k = -blur.radius; k <= blur.radius; ++k) {
        ivec2 p = clamp(c + dir * k, ivec2(0), blur.aoSize - 1);
        float w = exp(-0.5 * float(k * k) / (blur.sigma * blur.sigma));
        if (blur.mode == SSAO_BLUR_MODE_BILATERAL) w *= 1.0 / (blur.delta + abs(zc - linearDepthAt(p)));
        sum += w * texelFetch(uAo, p, 0).r;
        weights += w;
    }
    outOcclusion = sum / weights;
}
