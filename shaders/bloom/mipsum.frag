#version 450 core
// Ferko's bloom (seed 000 section 5.4): mipmaps of the thresholded image are
// blurred copies of it; the bloom is their average over levels 1..n.
#include "../common/bindings.glsl"

layout(binding = 0) uniform sampler2D uBright;
layout(std140, binding = PASS_UBO) uniform BloomParams {
    ivec4 modes;   // y levels
    vec4 values;   // zw texel of the target
} bloom;

out vec4 outColor;

void main() {
    vec2 uv = gl_FragCoord.xy * bloom.values.zw;
    vec3 sum = vec3(0.0);
    for (int level = 1; level <= bloom.modes.y; ++level) sum += textureLod(uBright, uv, float(level)).rgb;
    // An image so small that the bright image has no coarser level.
    if (bloom.modes.y == 0) sum = textureLod(uBright, uv, 0.0).rgb;
    outColor = vec4(sum / float(max(bloom.modes.y, 1)), 1.0);
}
