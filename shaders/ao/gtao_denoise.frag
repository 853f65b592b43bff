#version 450 core
// GTAO's own spatial denoise (gtao.denoise = edge_aware), in place of the
// shared blur: the mean of gtao.noisy over a 5x5 window of AO pixels with
// tent weights (1/2, 1, 1, 1, 1/2) per axis, so every cell of gtao.frag's 4x4
// rotation pattern counts exactly once, times an edge weight in the spirit of
// XeGTAO's denoiser: exp(-(distance of the neighbour's point from the
// centre's tangent plane / (gtao.denoisePlane x depth))^2) and the normals'
// agreement, so a floor does not take the AO of the object standing on it.
// Writes ao.raw at the AO resolution.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/gbuffer.glsl"
#include "../params/gtao.h"

layout(binding = GTAO_DEPTH_TEXTURE) uniform sampler2D uDepth;
layout(binding = GTAO_NORMAL_TEXTURE) uniform sampler2D uNormal;
layout(binding = GTAO_NOISY_TEXTURE) uniform sampler2D uNoisy;

out float outVisibility;

ivec2 fullPixel(ivec2 aoPx) {
    return min((aoPx << gtao.shift) + ((1 << gtao.shift) >> 1), ivec2(camera.viewport.xy) - 1);
}

void main() {
    ivec2 aoPx = ivec2(gl_FragCoord.xy);
    ivec2 px = fullPixel(aoPx);
    float depth = texelFetch(uDepth, px, 0).r;
    if (isFarDepth(depth)) {
        outVisibility = 1.0;
        return;
    }
    vec3 P = viewPositionAtPixel(px, depth);
    vec3 N = decodeNormalKL(texelFetch(uNormal, px, 0).xy);
    float scale = gtao.denoisePlane * max(-P.z, 1e-6);
    float sum = 0.0, weights = 0.0;
    for (int j = -2; j <= 2; ++j)
        for (int i = -2; i <= 2; ++i) {
            ivec2 q = aoPx + ivec2(i, j);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, gtao.aoSize))) continue;
            ivec2 qPx = fullPixel(q);
            float d = texelFetch(uDepth, qPx, 0).r;
            if (isFarDepth(d)) continue;
            vec3 S = viewPositionAtPixel(qPx, d);
            vec3 Nq = decodeNormalKL(texelFetch(uNormal, qPx, 0).xy);
            float plane = dot(S - P, N) / scale;
            float w = (abs(i) == 2 ? 0.5 : 1.0) * (abs(j) == 2 ? 0.5 : 1.0);
            w *= exp(-plane * plane) * pow(max(dot(N, Nq), 0.0), 8.0);
            sum += w * texelFetch(uNoisy, q, 0).r;
            weights += w;
        }
    outVisibility = weights > 0.0 ? sum / weights : texelFetch(uNoisy, aoPx, 0).r;
}
