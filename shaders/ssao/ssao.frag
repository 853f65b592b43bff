#version 450 core
// Screen-space ambient occlusion (seed 000 sections 4.6.3 and 5.6, seed 002
// section 5.1): reconstruct the view-space position from depth, offset it by
// kernel vectors reflected about a per-pixel random vector and flipped into
// the normal's hemisphere, project each point back, and count it occluded when
// the depth buffer holds a surface in front of it, weighted by the falloff
// 1 / (1 + d^2) (eq. 4.6) and a range check against depth discontinuities.
// Runs at the AO resolution; reads the full-resolution G-buffer (its depth
// with linear filtering, see below).
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/gbuffer.glsl"
#include "../params/ssao.h"

layout(binding = SSAO_DEPTH_TEXTURE) uniform sampler2D uDepth;
layout(binding = SSAO_NORMAL_TEXTURE) uniform sampler2D uNormal;
layout(binding = SSAO_NOISE_TEXTURE) uniform sampler2D uNoise;   // random unit vectors, SSAO_NOISE_SIZE^2, repeated

out float outOcclusion;

// The filtered depth at uv. Between the outermost pixel centres and the
// image's edge, clamp-to-edge filtering would hold the edge pixel's depth
// constant (a receding floor would then rise in front of its own samples and
// darken the border rows, the more so the fewer pixels the radius spans);
// there the depth is extrapolated linearly from the two outermost pixels,
// which is exact for a plane, as the filtered depth is inside.
float depthAt(vec2 uv) {
    vec2 size = vec2(textureSize(uDepth, 0));
    vec2 texel = 1.0 / size;
    vec2 inside = clamp(uv, 0.5 * texel, 1.0 - 0.5 * texel);
    float d = texture(uDepth, inside).r;
    vec2 beyond = (uv - inside) * size;  // texels past the outermost centre, |.| <= 0.5
    if (beyond.x != 0.0) {
        float inner = texture(uDepth, inside - vec2(sign(beyond.x) * texel.x, 0.0)).r;
        if (!isFarDepth(inner)) d += (d - inner) * abs(beyond.x);
    }
    if (beyond.y != 0.0) {
        float inner = texture(uDepth, inside - vec2(0.0, sign(beyond.y) * texel.y)).r;
        if (!isFarDepth(inner)) d += (d - inner) * abs(beyond.y);
    }
    return d;
}

void main() {
    // The full-resolution pixel this AO pixel stands for (its centre).
    vec2 uv = (gl_FragCoord.xy) / vec2(ssao.aoSize);
    ivec2 px = ivec2(uv * camera.viewport.xy);
    float depth = texelFetch(uDepth, px, 0).r;
    if (isFarDepth(depth)) {
        outOcclusion = 1.0;
        return;
    }
    vec3 P = viewPositionAtPixel(px, depth);
    vec3 N = decodeNormal(texelFetch(uNormal, px, 0).xy);
    vec3 r = normalize(texelFetch(uNoise, ivec2(gl_FragCoord.xy) & (SSAO_NOISE_SIZE - 1), 0).xyz);
    float radius = ssao.radius;
    float bias = ssao.bias * radius;
    int n = ssao.sampleCount;
    float occlusion = 0.0;
    for (int i = 0; i < n; ++i) {
        vec3 s = reflect(ssao.kernel[i].xyz, r);
        if (dot(s, N) < 0.0) s = -s;  // into the hemisphere above the surface
        vec3 Q = P + s * radius;
        vec4 clip = camera.projection * vec4(Q, 1.0);
        vec2 quv = clip.xy / clip.w * 0.5 + 0.5;
        if (any(lessThan(quv, vec2(0.0))) || any(greaterThanEqual(quv, vec2(1.0)))) continue;
        // Depth is affine across a plane in window space, so the bilinearly
        // filtered depth at Q's exact projection is the surface on Q's ray;
        // the nearest pixel centre would make flat surfaces occlude themselves.
        float sceneDepth = depthAt(quv);
        if (isFarDepth(sceneDepth)) continue;
        vec3 S = viewPositionFromDepth(quv, sceneDepth);
        if (S.z < Q.z + bias) continue;  // the stored surface is behind the sample: not occluded
        // The falloff 1 / (1 + d^2) with d in units of the radius, so the AO
        // does not change when the scene and the radius scale together (the
        // same as the seed's for the default radius of 1).
        float d = length(S - P) / radius;
        float weight = 1.0 / (1.0 + d * d);
        if (ssao.rangeCheck != 0) {
            // A surface far in front of P (another object) does not occlude it.
            float gap = abs(P.z - S.z);
            weight *= gap <= radius ? 1.0 : radius / gap;
        }
        occlusion += weight;
    }
    outOcclusion = clamp(1.0 - ssao.intensity * occlusion / float(max(n, 1)), 0.0, 1.0);
}
