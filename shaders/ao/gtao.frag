#version 450 core
// Ground-truth ambient occlusion (Jimenez, Wu, Pesce and Jarabo, "Practical
// Real-Time Strategies for Accurate Indirect Occlusion", 2016; Intel's
// XeGTAO is the reference implementation). For each of gtao.slices
// screen-space directions phi, the slice is the plane through the eye, the
// point and that direction; gtao.steps depth samples per side along it find
// the two horizon angles h0 (towards -phi) and h1 (towards +phi), measured
// from the view vector V in the slice, each clamped to the hemisphere about
// the normal's projection into the slice (angle n from V, length |Np|). The
// cosine-weighted visibility of the slice is the paper's closed form (eq. 10)
//     a(phi) = |Np| / 4 (-cos(2 h0 - n) + cos n + 2 h0 sin n
//                        -cos(2 h1 - n) + cos n + 2 h1 sin n),
// averaged over the slices: 1 on an open plane, the cosine-weighted share of
// the hemisphere the horizons leave open elsewhere. A sample further than
// (1 - falloff) of the radius fades towards the hemisphere's edge (XeGTAO's
// linear falloff); the thickness heuristic (the paper's section 4.3) lets a
// horizon sink back towards a lower sample, so thin occluders do not shadow
// everything behind them; with gtao.thin_occluders a sample that looks
// thin shades only the angle it subtends (thinWidth below). Runs at the AO
// resolution; reads the
// full-resolution G-buffer.
//
// Bent normal (gtao.bent_normals; docs/ao.md derives it): the
// cosine-weighted mean unoccluded direction B = Int V(w) w (N.w) dw. In a
// slice a direction is d(t) = sin t T + cos t V (t from V, towards T), its
// cosine to N is |Np| cos(t - n) and the measure |sin t| dt, so the slice
// adds |Np| (bT T + bV V) with, per side of horizon h (the same expression
// for both sides, h < 0 on the T- side):
//     bT(h) = cos n sin^3 h / 3 + sin n (2/3 - cos h + cos^3 h / 3)
//     bV(h) = cos n (1 - cos^3 h) / 3 + sin n sin^3 h / 3
// normalised at the end. On an open plane this is N exactly for any set of
// slices (the test checks it).
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/gbuffer.glsl"
#include "../params/gtao.h"

layout(binding = GTAO_DEPTH_TEXTURE) uniform sampler2D uDepth;
layout(binding = GTAO_NORMAL_TEXTURE) uniform sampler2D uNormal;

layout(location = 0) out float outVisibility;
layout(location = 1) out vec4 outBentNormal;  // only attached with gtao.bent_normals

const float PI = 3.14159265358979;
const float HALF_PI = 1.57079632679490;

// The view-space point at a full-resolution position (in pixels), or false
// on the sky or off the image. The depth is filtered (the pass binds a
// linear sampler): depth is affine across a plane in window space, so the
// point is on the slice's own line; the nearest pixel centre would lie off
// the slice, and a flat floor would occlude itself at grazing angles.
bool sampleAt(vec2 fullPx, out vec3 S) {
    vec2 size = camera.viewport.xy;
    if (any(lessThan(fullPx, vec2(0.5))) || any(greaterThan(fullPx, size - 0.5))) return false;
    vec2 uv = fullPx / size;
    // A filtered depth between a surface and the sky is no surface.
    vec4 texels = textureGather(uDepth, uv, 0);
    if (isFarDepth(texels.x) || isFarDepth(texels.y) || isFarDepth(texels.z) || isFarDepth(texels.w)) return false;
    float d = textureLod(uDepth, uv, 0.0).r;
    S = viewPositionFromDepth(uv, d);
    return true;
}

// One side's share of a slice's bent normal, in the slice's (T, V) basis.
vec2 bentSide(float h, float cosN, float sinN) {
    float c = cos(h), s = sin(h);
    float s3 = s * s * s, c3 = c * c * c;
    return vec2(cosN * s3 / 3.0 + sinN * (2.0 / 3.0 - c + c3 / 3.0), cosN * (1.0 - c3) / 3.0 + sinN * s3 / 3.0);
}

// Thin occluders (gtao.thin_occluders; docs/ao.md "Thin occluders"). The
// depth buffer holds an occluder's front only, and the horizon takes it as
// infinitely thick: a pole before a wall shaded the wall as a wall would
// (2.8x the ray-traced occlusion). What the screen does show is the
// occluder's width along the slice, and solids are about as wide as they
// stand out. A sample S standing `gap` in front of P (view depth) looks thin
// when, `gap` further out along the slice (in pixels at S's depth), P's own
// surface is back: the probe Q within (-gap/2, gap/4) of P's depth and within
// 1.6 gap of S (a pole's probe lands on the wall about 1.41 gap away; a box's
// top seen at a grazing angle spans few pixels, and a probe that jumped
// across it to the floor behind lands much further, so the box stays solid).
bool backToP(vec3 P, vec3 Q, float gap) { return Q.z < P.z + 0.25 * gap && Q.z > P.z - 0.5 * gap; }

// The width beyond S along the slice (world units) of an occluder that looks
// thin, or 0 when it does not. Probes 1, 2, 4, ... pixels out find the first
// one where P's surface is back; the edge lies between it and the one before
// (d/2 and d): 0.75 d. The width beyond S, not the whole width: probing back
// towards P as well over-shaded poles a few pixels wide, whose 1-pixel
// probes overstate them (docs/ao.md). At most 16 probes.
float thinWidth(vec3 P, vec3 S, vec2 samplePx, vec2 outward) {
    float gap = S.z - P.z;  // view space looks down -z: S nearer the eye has the larger z
    if (gap <= 0.0) return 0.0;
    float pxPerUnit = gtao.pixelScale / max(-S.z, 1e-6);
    float px = max(gap * pxPerUnit, 1.0);
    vec3 Q;
    if (!sampleAt(samplePx + outward * px, Q)) return 0.0;  // off the image or sky: no evidence
    if (!backToP(P, Q, gap) || length(Q - S) >= 1.6 * gap) return 0.0;
    float d = 1.0;
    for (int k = 0; k < GTAO_MAX_WIDTH_PROBES && d < px; ++k, d *= 2.0)
        if (sampleAt(samplePx + outward * d, Q) && backToP(P, Q, gap)) return 0.75 * d / pxPerUnit;
    return 0.75 * px / pxPerUnit;
}

// One side's horizon update: the sample's cosine to V, faded towards the
// side's lowest cosine by the falloff; a thin-looking sample raises it by
// (1 - gtao.thin_occluders) of its rise only, and the side keeps the highest
// such sample in `thin` (its cosine, and the angle it subtends from P,
// width / distance) for main() to shade that angle alone; then the
// thickness heuristic.
float updateHorizon(float horizonCos, float lowCos, vec3 P, vec3 V, vec3 S, vec2 samplePx, vec2 outward,
                    inout vec2 thin) {
    vec3 delta = S - P;
    float dist = length(delta);
    if (dist <= 0.0) return horizonCos;
    float c = dot(delta / dist, V);
    float weight = gtao.falloff > 0.0 ? clamp((gtao.radius - dist) / (gtao.falloff * gtao.radius), 0.0, 1.0)
                                      : (dist < gtao.radius ? 1.0 : 0.0);
    c = mix(lowCos, c, weight);
    if (gtao.thinOccluders > 0.0 && c > horizonCos) {
        float w = thinWidth(P, S, samplePx, outward);
        if (w > 0.0) {
            if (c > thin.x) thin = vec2(c, w / dist);
            c = mix(c, lowCos, gtao.thinOccluders);
        }
    }
    float h = c > horizonCos ? c : mix(horizonCos, c, gtao.thickness);
    return max(h, lowCos);
}

// 4 / |Np| times the slice's cosine-weighted visibility between V and the
// horizon angle h (either side; Jimenez et al. eq. 10, one side of it).
float sideVisibility(float h, float n, float cosN, float sinN) { return cosN + 2.0 * h * sinN - cos(2.0 * h - n); }

void main() {
    ivec2 aoPx = ivec2(gl_FragCoord.xy);
    // The full-resolution pixel this AO pixel stands for: the one at its
    // centre, as the upsampling takes it (ssao/upsample.frag).
    ivec2 px = min((aoPx << gtao.shift) + ((1 << gtao.shift) >> 1), ivec2(camera.viewport.xy) - 1);
    float depth = texelFetch(uDepth, px, 0).r;
    if (isFarDepth(depth)) {
        outVisibility = 1.0;
        outBentNormal = vec4(0.0);
        return;
    }
    // Moved a little towards the eye (as XeGTAO does): depth quantisation
    // would otherwise lift plane samples above their own plane's horizon.
    vec3 P = viewPositionAtPixel(px, depth) * 0.9992;
    vec3 N = decodeNormalKL(texelFetch(uNormal, px, 0).xy);
    vec3 V = normalize(-P);
    // The radius in full-resolution pixels at this depth.
    float screenRadius = gtao.radius * gtao.pixelScale / max(-P.z, 1e-6);
    // A 4x4 pattern of slice rotations and step offsets, which the shared
    // blur averages away (no frame dependence). Every 4 pixels of a row hold
    // the 4 quarters of the rotations (the column picks the quarter, the row
    // the offset inside it): on a floor seen at a grazing angle the
    // bilateral blur hardly mixes rows, whose depths differ, but a row's
    // pixels share theirs.
    vec2 cell = vec2(aoPx & 3);
    float sliceNoise = (cell.x + (cell.y + 0.5) * 0.25) * 0.25;
    float stepNoise = (cell.y + (cell.x + 0.5) * 0.25) * 0.25;
    vec2 centre = vec2(px) + 0.5;

    float visibility = 0.0;
    vec3 bent = vec3(0.0);
    int slices = clamp(gtao.slices, 1, GTAO_MAX_SLICES);
    int steps = clamp(gtao.steps, 1, GTAO_MAX_STEPS);
    // The slices' directions are uniform about V (the integral's measure),
    // not on the screen: off the image's centre the two differ by the
    // perspective, which biased an open floor by a few per cent.
    vec3 X = normalize(vec3(V.z, 0.0, -V.x));
    vec3 Y = cross(V, X);
    for (int i = 0; i < slices; ++i) {
        float phi = (float(i) + sliceNoise) * PI / float(slices);
        vec3 T = cos(phi) * X + sin(phi) * Y;  // in the slice, perpendicular to V
        // The slice's direction on the screen: where P + t T moves as t grows
        // (the derivative of the projection; pixels are square).
        vec2 omega = normalize(T.xy * -P.z + P.xy * T.z);
        vec3 A = cross(T, V);                  // the slice plane's normal
        vec3 Np = N - A * dot(N, A);
        float len = length(Np);
        if (len < 1e-6) continue;  // the normal is the slice's axis: the slice weighs |Np| = 0
        float cosN = clamp(dot(Np, V) / len, -1.0, 1.0);
        float n = (dot(Np, T) < 0.0 ? -1.0 : 1.0) * acos(cosN);
        float low1 = cos(n + HALF_PI), low0 = cos(n - HALF_PI);
        float hc1 = low1, hc0 = low0;
        vec2 thin1 = vec2(-2.0, 0.0), thin0 = vec2(-2.0, 0.0);  // no thin occluder yet
        for (int j = 0; j < steps; ++j) {
            float s = (float(j) + stepNoise) / float(steps);
            float offset = s * s * screenRadius + gtao.minPixels;
            vec3 S;
            vec2 px1 = centre + omega * offset, px0 = centre - omega * offset;
            if (sampleAt(px1, S)) hc1 = updateHorizon(hc1, low1, P, V, S, px1, omega, thin1);
            if (sampleAt(px0, S)) hc0 = updateHorizon(hc0, low0, P, V, S, px0, -omega, thin0);
        }
        float h1 = acos(clamp(hc1, -1.0, 1.0));
        float h0 = -acos(clamp(hc0, -1.0, 1.0));
        h1 = n + min(h1 - n, HALF_PI);
        h0 = n + max(h0 - n, -HALF_PI);
        float sinN = sin(n);
        float open = sideVisibility(h0, n, cosN, sinN) + sideVisibility(h1, n, cosN, sinN);
        // A thin occluder shades the angle it subtends, from its front towards
        // the hemisphere's edge, where the horizon left that open; weighted
        // by gtao.thin_occluders, the share of its rise the horizon lost.
        if (thin1.x > -2.0) {
            float a = acos(clamp(thin1.x, -1.0, 1.0)), b = min(a + thin1.y, h1);
            if (a < b) open -= gtao.thinOccluders * (sideVisibility(b, n, cosN, sinN) - sideVisibility(a, n, cosN, sinN));
        }
        if (thin0.x > -2.0) {
            float a = -acos(clamp(thin0.x, -1.0, 1.0)), b = max(a - thin0.y, h0);
            if (b < a) open -= gtao.thinOccluders * (sideVisibility(b, n, cosN, sinN) - sideVisibility(a, n, cosN, sinN));
        }
        visibility += len * 0.25 * open;
        if (gtao.bentNormals != 0) {
            vec2 b = bentSide(h0, cosN, sinN) + bentSide(h1, cosN, sinN);
            bent += len * (b.x * T + b.y * V);
        }
    }
    // Fully occluded (no open direction): the surface normal.
    outBentNormal = vec4(dot(bent, bent) > 1e-12 ? normalize(bent) : N, 0.0);
    // Not clamped to 1: a slice's share |Np| a(phi) of an open hemisphere is
    // cos n + n sin n times |Np|, above 1 for some directions and below for
    // others, 1 only on average over phi; the shared filter averages the 4x4
    // rotations and clamps (ssao/upsample.frag).
    outVisibility = max(visibility / float(slices), 0.0);
}
