#version 450 core
// Bloom threshold (seed 000 section 5.4, seed 002 section 3.2, step 7): the
// L-buffer at half resolution (the mean of each 2x2 block, so a one-pixel
// highlight is not dropped or flickering), with the threshold, a multiple of
// the image's average luminance, subtracted from each pixel's luminance.
#include "../common/bindings.glsl"
#include "../common/color.glsl"
#include "../params/bloom.h"

layout(binding = BLOOM_HDR_TEXTURE) uniform sampler2D uHdr;
layout(binding = BLOOM_STATS_TEXTURE) uniform sampler2D uStats;

out vec4 outColor;

vec3 guarded(vec3 c) {
    if (bloom.nanGuard == 0) return c;
    return isFiniteVec(c) ? max(c, vec3(0.0)) : vec3(0.0);
}

void main() {
    ivec2 size = textureSize(uHdr, 0);
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    vec3 c = vec3(0.0);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) c += guarded(texelFetch(uHdr, min(p + ivec2(i, j), size - 1), 0).rgb);
    c *= 0.25;
    float L = luminance(c);
    float t = bloom.threshold * texelFetch(uStats, ivec2(0), 0).x;
    // The bloom chain is half float: radiance past its largest value (65504)
    // would turn to infinity there, so it is clamped (the L-buffer is 32-bit).
    outColor = vec4(min(L > t ? c * (L - t) / L : vec3(0.0), vec3(65504.0)), 1.0);
}
