#version 450 core
// Ferko's bloom (seed 000 section 5.4): mipmaps of the thresholded image are
// blurred copies of it; the bloom is their average over levels 1..n.
#include "../params/bloom.h"

layout(binding = 0) uniform sampler2D uBright;

out vec4 outColor;

void main() {
    vec2 uv = gl_FragCoord.xy * bloom.targetTexel;
    vec3 sum = vec3(0.0);
    for (int level = 1; level <= bloom.levels; ++level) sum += textureLod(uBright, uv, float(level)).rgb;
    // An image so small that the bright image has no coarser level.
    if (bloom.levels == 0) sum = textureLod(uBright, uv, 0.0).rgb;
    outColor = vec4(sum / float(max(bloom.levels, 1)), 1.0);
}
