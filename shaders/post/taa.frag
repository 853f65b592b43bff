#version 450 core
// Temporal anti-aliasing (aa.method=taa; Karis 2014, "High quality temporal
// supersampling"): the frame was rendered with its projection jittered by a
// sub-pixel Halton(2,3) offset; the history (last frame's result) is read
// where this pixel's surface was last frame (reprojected from depth and the
// camera's motion, unjittered), clamped into the 3x3 neighbourhood's
// min/max box of this frame in YCoCg, and blended with this frame by
// aa.taa_blend. History that falls off screen, or that the clamp moves by
// more than aa.taa_reject (YCoCg distance, display units 0-1), is thrown
// away: the pixel takes this frame alone and taa.rejected is 1 there.
#include "../common/bindings.glsl"
#include "../params/taa.h"

layout(binding = TAA_CURRENT_TEXTURE) uniform sampler2D uCurrent;
layout(binding = TAA_HISTORY_TEXTURE) uniform sampler2D uHistory;  // bilinear
layout(binding = TAA_DEPTH_TEXTURE) uniform sampler2D uDepth;

layout(location = 0) out vec4 outColor;
layout(location = 1) out float outRejected;

vec3 toYCoCg(vec3 c) {
    return vec3(dot(c, vec3(0.25, 0.5, 0.25)), dot(c, vec3(0.5, 0.0, -0.5)), dot(c, vec3(-0.25, 0.5, -0.25)));
}
vec3 fromYCoCg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

void main() {
    const ivec2 px = ivec2(gl_FragCoord.xy);
    const ivec2 size = textureSize(uCurrent, 0);
    const vec3 current = texelFetch(uCurrent, px, 0).rgb;
    outColor = vec4(current, 1.0);
    outRejected = 1.0;
    if (taa.historyValid == 0) return;

    vec3 lo = vec3(1e30), hi = vec3(-1e30);
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            const vec3 c = toYCoCg(texelFetch(uCurrent, clamp(px + ivec2(i, j), ivec2(0), size - 1), 0).rgb);
            lo = min(lo, c);
            hi = max(hi, c);
        }
    const float depth = texelFetch(uDepth, px, 0).r;
    const vec2 ndc = (vec2(px) + 0.5) / vec2(size) * 2.0 - 1.0;
    const vec4 clip = taa.reprojection * vec4(ndc, depth, 1.0);
    const vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (!(clip.w > 0.0) || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return;  // off screen

    const vec3 history = toYCoCg(textureLod(uHistory, uv, 0.0).rgb);
    const vec3 clamped = clamp(history, lo, hi);
    if (distance(clamped, history) > taa.rejectDistance) return;  // the surface is not what it was
    outColor = vec4(mix(fromYCoCg(clamped), current, taa.blend), 1.0);
    outRejected = 0.0;
}
