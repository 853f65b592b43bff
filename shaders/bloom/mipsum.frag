#version 450 core
// Ferko's bloom (seed 000 section 5.4): blurred, successively halved copies of
// the thresholded image, averaged over levels 1..n. The copies are the
// filtered downsample chain (bloom/down.frag: 13 taps, a tent-like low-pass,
// not a 2x2 box mip), and each is read back with a cubic B-spline (four
// bilinear taps; Sigg and Hadwiger, GPU Gems 2 ch. 20) rather than bilinearly:
// a box mip chain read bilinearly turns one bright pixel into a square
// snapped to the coarsest level's grid, off its source's centre.
#include "../common/bindings.glsl"
#include "../params/bloom.h"

layout(binding = BLOOM_BRIGHT_TEXTURE) uniform sampler2D uBright;     // level 0 (when there is no coarser level)
layout(binding = BLOOM_LEVELS_TEXTURE) uniform sampler2D uLevels[6];  // the downsample chain, levels 1..6

out vec4 outColor;

vec3 bspline(sampler2D tex, vec2 uv) {
    vec2 size = vec2(textureSize(tex, 0));
    vec2 p = uv * size - 0.5;
    vec2 i = floor(p), f = p - i;
    vec2 f2 = f * f, f3 = f2 * f;
    vec2 w0 = (-f3 + 3.0 * f2 - 3.0 * f + 1.0) / 6.0;
    vec2 w1 = (3.0 * f3 - 6.0 * f2 + 4.0) / 6.0;
    vec2 w2 = (-3.0 * f3 + 3.0 * f2 + 3.0 * f + 1.0) / 6.0;
    vec2 w3 = f3 / 6.0;
    vec2 g0 = w0 + w1, g1 = w2 + w3;
    vec2 t0 = (i - 0.5 + w1 / g0) / size;  // i + 0.5 + (w1 / g0 - 1)
    vec2 t1 = (i + 1.5 + w3 / g1) / size;
    return g0.y * (g0.x * texture(tex, vec2(t0.x, t0.y)).rgb + g1.x * texture(tex, vec2(t1.x, t0.y)).rgb) +
           g1.y * (g0.x * texture(tex, vec2(t0.x, t1.y)).rgb + g1.x * texture(tex, vec2(t1.x, t1.y)).rgb);
}

void main() {
    vec2 uv = gl_FragCoord.xy * bloom.targetTexel;
    vec3 sum = vec3(0.0);
    for (int level = 1; level <= bloom.levels; ++level) sum += bspline(uLevels[level - 1], uv);
    // An image so small that the bright image has no coarser level.
    if (bloom.levels == 0) sum = texture(uBright, uv).rgb;
    outColor = vec4(sum / float(max(bloom.levels, 1)), 1.0);
}
