#version 450 core
// Dual-filter bloom, upsample (Jimenez 2014): a 3x3 tent of the coarser
// level added to this level's downsampled image, so each level keeps its own
// detail and the blur grows level by level.
#include "../common/bindings.glsl"
#include "../params/bloom.h"

layout(binding = BLOOM_COARSE_TEXTURE) uniform sampler2D uCoarse;
layout(binding = BLOOM_SAME_TEXTURE) uniform sampler2D uSame;

out vec4 outColor;

void main() {
    vec2 uv = gl_FragCoord.xy * bloom.targetTexel;
    vec2 t = bloom.sourceTexel;
    vec3 s = texture(uCoarse, uv + vec2(-t.x, t.y)).rgb + texture(uCoarse, uv + vec2(0, t.y)).rgb * 2.0 +
             texture(uCoarse, uv + vec2(t.x, t.y)).rgb + texture(uCoarse, uv + vec2(-t.x, 0)).rgb * 2.0 +
             texture(uCoarse, uv).rgb * 4.0 + texture(uCoarse, uv + vec2(t.x, 0)).rgb * 2.0 +
             texture(uCoarse, uv + vec2(-t.x, -t.y)).rgb + texture(uCoarse, uv + vec2(0, -t.y)).rgb * 2.0 +
             texture(uCoarse, uv + vec2(t.x, -t.y)).rgb;
    outColor = vec4(min(s / 16.0 + texture(uSame, uv).rgb, vec3(65504.0)), 1.0);  // half float: stay finite
}
