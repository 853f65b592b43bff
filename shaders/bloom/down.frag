#version 450 core
// Dual-filter bloom, downsample (Jimenez, "Next generation post processing
// in Call of Duty: Advanced Warfare", 2014): 13 bilinear taps as five
// overlapping 2x2 boxes, weights 0.5 (centre box) and 0.125 (corner boxes).
#include "../common/bindings.glsl"
#include "../params/bloom.h"

layout(binding = BLOOM_SOURCE_TEXTURE) uniform sampler2D uSource;

out vec4 outColor;

vec3 tap(vec2 uv, vec2 o) { return texture(uSource, uv + o * bloom.sourceTexel).rgb; }

void main() {
    vec2 uv = gl_FragCoord.xy * bloom.targetTexel;
    vec3 a = tap(uv, vec2(-2, 2)), b = tap(uv, vec2(0, 2)), c = tap(uv, vec2(2, 2));
    vec3 d = tap(uv, vec2(-2, 0)), e = tap(uv, vec2(0, 0)), f = tap(uv, vec2(2, 0));
    vec3 g = tap(uv, vec2(-2, -2)), h = tap(uv, vec2(0, -2)), i = tap(uv, vec2(2, -2));
    vec3 j = tap(uv, vec2(-1, 1)), k = tap(uv, vec2(1, 1)), l = tap(uv, vec2(-1, -1)), m = tap(uv, vec2(1, -1));
    vec3 sum = (j + k + l + m) * 0.125 + (a + c + g + i) * 0.03125 + (b + d + f + h) * 0.0625 + e * 0.125;
    outColor = vec4(sum, 1.0);
}
