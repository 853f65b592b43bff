#version 450 core
// Depth of field (seed 004 "Depth of Field", with the focal distance its
// "moving forward" section asks for), with the near field as its own layer
// as the gather-based methods do it (Sousa, "CryENGINE 3 Graphics Gems",
// SIGGRAPH 2013; Jimenez, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare", SIGGRAPH 2014).
// Reads: uImage (the post chain's image), uDepth (gbuffer.depth).
// Writes: outColor (dof.result), or the signed circle of confusion (dof.coc),
// or the near layer's alpha (dof.near_alpha).
//
// A circle of confusion from view depth: zero within focus_range around
// focus_distance, growing to max_radius one focus_range beyond it, for the
// far field and (optionally) the near field (negative: nearer than the focus).
//
// Background layer (the in-focus and far field): a gather over a golden-angle
// disc of max_radius; a sample counts when it is not near-field and, if it is
// nearer than the centre, its own blur reaches the centre, if farther, the
// centre's blur reaches it (so a sharp foreground does not smear into a
// blurred background and the background does not bleed over it). Behind a
// near-field pixel it is filled from the background samples around it.
//
// Near layer: an out-of-focus object in front spreads over what is behind it
// (pmndrs/postprocessing#176: a gather that lets near samples win dilates the
// object with a hard rim). Each near-field pixel scatters its colour over its
// disc of radius c, 1/(pi c^2) of it per pixel; gathered, a sample standing for
// pi R^2 / n pixels of a disc of radius R adds R^2 / (n c^2) to the coverage
// alpha where its disc reaches the centre. R is the near circle of confusion
// dilated: the largest near disc that reaches the centre (a first gather over
// max_radius), so the n samples of the second gather are spread over the disc
// that matters. Over a straight edge of a wide object alpha is 1/2 at the
// silhouette and falls with the area of the disc's segment to 0 one radius
// out; the near colour is the coverage-weighted mean (premultiplied by alpha)
// and is composited over the background layer with alpha.
// The image is the tone mapper's 8-bit output; with srgbInput set it is
// sRGB-encoded, and both layers average linear light, then re-encode.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/color.glsl"
#include "../params/dof.h"

layout(binding = DOF_IMAGE_TEXTURE) uniform sampler2D uImage;
layout(binding = DOF_DEPTH_TEXTURE) uniform sampler2D uDepth;

layout(location = 0) out vec4 outColor;

const float kGoldenAngle = 2.39996323;

float linearDepth(ivec2 px) {
    float d = texelFetch(uDepth, px, 0).r;
    return isFarDepth(d) ? camera.clip.y : -viewPositionAtPixel(px, d).z;
}

// Signed circle of confusion in pixels: negative in front of the focus.
float coc(float z) {
    float d = z - dof.focusDistance;
    float halfRange = 0.5 * dof.focusRange;
    float t = clamp((abs(d) - halfRange) / max(dof.focusRange, 1e-3), 0.0, 1.0);
    if (d < 0.0 && dof.nearBlur == 0) return 0.0;
    if (d > 0.0 && dof.farBlur == 0) return 0.0;
    return sign(d) * t * dof.maxRadius;
}

// The near-field disc radius of a pixel with circle of confusion c: 0 when it
// is not in front of the focus, at least half a pixel (a pixel's own disc).
float nearRadius(float c) { return c < 0.0 ? max(-c, 0.5) : 0.0; }

vec3 readLinear(ivec2 q) {
    vec3 c = texelFetch(uImage, q, 0).rgb;
    return dof.srgbInput != 0 ? srgbToLinear(c) : c;
}

// Sample i of n on a golden-angle (Vogel) disc of radius R: its radius r, each
// sample standing for an equal share of the disc's area.
vec2 discSample(int i, int n, float R, out float r) {
    r = R * sqrt((float(i) + 0.5) / float(n));
    float a = float(i) * kGoldenAngle;
    return r * vec2(cos(a), sin(a));
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uImage, 0);
    float zc = linearDepth(px);
    float cc = coc(zc);
    if (dof.outputKind == DOF_WRITE_COC) {
        outColor = vec4(cc, 0.0, 0.0, 1.0);
        return;
    }
    int n = dof.sampleCount;
    float maxR = dof.maxRadius;

    // Background layer. What lies behind a near-field centre is not in the
    // image: it is filled from the samples within the centre's near blur that
    // are not near-field themselves (the background next to the object, which
    // its blurred edge partly shows), or is the centre's own colour where the
    // disc holds none (there the near layer covers it).
    bool nearCentre = cc < 0.0;
    vec3 centre = readLinear(px);
    vec3 sum = nearCentre ? vec3(0.0) : centre;
    float weights = nearCentre ? 0.0 : 1.0;
    for (int i = 1; i < n; ++i) {
        float r = maxR * sqrt(float(i) / float(n));
        float a = float(i) * kGoldenAngle;
        ivec2 q = clamp(px + ivec2(round(r * vec2(cos(a), sin(a)))), ivec2(0), size - 1);
        float zq = linearDepth(q);
        float cq = coc(zq);
        float reach = nearCentre ? -cc : (zq < zc ? abs(cq) : min(abs(cq), cc));
        float w = cq < 0.0 ? 0.0 : clamp(reach - r + 1.0, 0.0, 1.0);
        sum += readLinear(q) * w;
        weights += w;
    }
    vec3 result = weights > 0.0 ? sum / weights : centre;

    // Near layer: the dilated near radius, then the coverage gather over it,
    // with twice the samples: its alpha moves in steps of one sample's share.
    int nNear = 2 * n;
    float nearR = nearRadius(cc), alpha = 0.0;
    for (int i = 0; i < nNear; ++i) {
        float r;
        vec2 o = discSample(i, nNear, maxR, r);
        ivec2 q = clamp(px + ivec2(round(o)), ivec2(0), size - 1);
        float c = nearRadius(coc(linearDepth(q)));
        if (c - r + 1.0 > 0.0) nearR = max(nearR, c);
    }
    if (nearR > 0.0) {
        vec3 nearSum = vec3(0.0);
        float coverage = 0.0;
        for (int i = 0; i < nNear; ++i) {
            float r;
            vec2 o = discSample(i, nNear, nearR, r);
            ivec2 q = clamp(px + ivec2(round(o)), ivec2(0), size - 1);
            float c = nearRadius(coc(linearDepth(q)));
            float w = c > 0.0 ? clamp(c - r + 1.0, 0.0, 1.0) / (c * c) : 0.0;
            nearSum += readLinear(q) * w;
            coverage += w;
        }
        alpha = min(coverage * nearR * nearR / float(nNear), 1.0);
        if (coverage > 0.0) result = mix(result, nearSum / coverage, alpha);
    }
    if (dof.outputKind == DOF_WRITE_NEAR_ALPHA) {
        outColor = vec4(alpha, 0.0, 0.0, 1.0);
        return;
    }
    outColor = vec4(dof.srgbInput != 0 ? linearToSrgb(result) : result, 1.0);
}
