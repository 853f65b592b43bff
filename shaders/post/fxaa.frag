#version 450 core
// FXAA (seed 000 section 3.3; after Lottes' FXAA 3.11 "quality" path): on the
// tone-mapped, sRGB-encoded image, find pixels whose local luma contrast is
// above the threshold, decide whether the edge runs horizontally or
// vertically, search along it in both directions for its ends, and shift the
// sample across the edge in proportion to how far the pixel is from the
// nearer end; blend in a sub-pixel low-pass for single-pixel features.
#include "../common/bindings.glsl"
#include "../params/fxaa.h"

layout(binding = FXAA_IMAGE_TEXTURE) uniform sampler2D uImage;

out vec4 outColor;

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }
float lumaAt(vec2 uv) { return luma(textureLod(uImage, uv, 0.0).rgb); }

void main() {
    vec2 texel = 1.0 / vec2(textureSize(uImage, 0));
    vec2 uv = gl_FragCoord.xy * texel;
    vec3 rgbM = textureLod(uImage, uv, 0.0).rgb;
    float M = luma(rgbM);
    float N = lumaAt(uv + vec2(0, texel.y)), S = lumaAt(uv - vec2(0, texel.y));
    float E = lumaAt(uv + vec2(texel.x, 0)), W = lumaAt(uv - vec2(texel.x, 0));
    float maxL = max(M, max(max(N, S), max(E, W)));
    float minL = min(M, min(min(N, S), min(E, W)));
    float range = maxL - minL;
    if (range < max(fxaa.edgeThresholdMin, maxL * fxaa.edgeThreshold)) {
        outColor = vec4(rgbM, 1.0);
        return;
    }
    float NW = lumaAt(uv + vec2(-texel.x, texel.y)), NE = lumaAt(uv + texel);
    float SW = lumaAt(uv - texel), SE = lumaAt(uv + vec2(texel.x, -texel.y));
    // Sub-pixel aliasing: how much the centre differs from its neighbourhood.
    float lowpass = (2.0 * (N + S + E + W) + NW + NE + SW + SE) / 12.0;
    float subpix = clamp(abs(lowpass - M) / range, 0.0, 1.0);
    subpix = smoothstep(0.0, 1.0, subpix);
    subpix = subpix * subpix * fxaa.subpixel;
    // Horizontal or vertical edge, from the second differences.
    float edgeH = abs(NW + SW - 2.0 * W) + 2.0 * abs(N + S - 2.0 * M) + abs(NE + SE - 2.0 * E);
    float edgeV = abs(NW + NE - 2.0 * N) + 2.0 * abs(W + E - 2.0 * M) + abs(SW + SE - 2.0 * S);
    bool horizontal = edgeH >= edgeV;
    float l1 = horizontal ? S : W, l2 = horizontal ? N : E;
    float g1 = abs(l1 - M), g2 = abs(l2 - M);
    float stepLength = horizontal ? texel.y : texel.x;
    float lumaLocal, gradient;
    if (g1 >= g2) {
        stepLength = -stepLength;
        lumaLocal = 0.5 * (l1 + M);
        gradient = g1;
    } else {
        lumaLocal = 0.5 * (l2 + M);
        gradient = g2;
    }
    vec2 edgeUv = uv + (horizontal ? vec2(0.0, 0.5 * stepLength) : vec2(0.5 * stepLength, 0.0));
    vec2 along = horizontal ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    float threshold = 0.25 * gradient;
    vec2 uv1 = edgeUv - along, uv2 = edgeUv + along;
    float e1 = lumaAt(uv1) - lumaLocal, e2 = lumaAt(uv2) - lumaLocal;
    bool done1 = abs(e1) >= threshold, done2 = abs(e2) >= threshold;
    for (int i = 1; i < fxaa.searchSteps && !(done1 && done2); ++i) {
        float stride = i < 3 ? 1.0 : (i < 6 ? 2.0 : 4.0);
        if (!done1) {
            uv1 -= along * stride;
            e1 = lumaAt(uv1) - lumaLocal;
            done1 = abs(e1) >= threshold;
        }
        if (!done2) {
            uv2 += along * stride;
            e2 = lumaAt(uv2) - lumaLocal;
            done2 = abs(e2) >= threshold;
        }
    }
    float d1 = horizontal ? uv.x - uv1.x : uv.y - uv1.y;
    float d2 = horizontal ? uv2.x - uv.x : uv2.y - uv.y;
    bool nearer1 = d1 < d2;
    float dist = min(d1, d2);
    float edgeLength = d1 + d2;
    // Only shift when the luma at the nearer end moves away from the centre's side.
    bool centerSmaller = M < lumaLocal;
    bool correct = ((nearer1 ? e1 : e2) < 0.0) != centerSmaller;
    float offset = correct ? 0.5 - dist / edgeLength : 0.0;
    offset = max(offset, subpix);
    vec2 finalUv = uv + (horizontal ? vec2(0.0, offset * stepLength) : vec2(offset * stepLength, 0.0));
    outColor = vec4(textureLod(uImage, finalUv, 0.0).rgb, 1.0);
}
