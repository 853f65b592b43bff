#version 450 core
// Tone mapping of the L-buffer to the displayable image (seed 000 sections
// 4.2 and 5.3; seed 002 step 9), with the bloom composited as the seed does
// it (step 10: on top of the tone-mapped image, blended by its luminance) or
// added in HDR before the operator.
//   simple:   L_d = L / (1 + L) on luminance                      (eq. 4.1)
//   reinhard: L = a / lum_log * L_w;
//             L_d = L (1 + L / L_white^2) / (1 + L) on luminance  (eqs. 4.3, 4.4)
//   aces:     Hill's fit of the ACES RRT + ODT, per channel
//   neutral:  Khronos PBR Neutral, per channel
//   clamp:    exposure only
// Luminance operators rescale RGB by L_d / L_w, which keeps chromaticity
// (the seed maps Y in XYZ). A guard replaces NaN and infinity first.
#include "../common/bindings.glsl"
#include "../common/color.glsl"
#include "../params/tonemap.h"

layout(binding = TONEMAP_HDR_TEXTURE) uniform sampler2D uHdr;
layout(binding = TONEMAP_STATS_TEXTURE) uniform sampler2D uStats;
layout(binding = TONEMAP_BLOOM_TEXTURE) uniform sampler2D uBloom;

in vec2 vUv;
out vec4 outColor;

vec3 guard(vec3 c) {
    if (tonemap.nanGuard == 0) return c;
    // NaN -> 0, +inf -> 1e38 (finite, and the L-buffer is RGBA32F: clamping
    // at the half-float maximum blacked out scenes brighter than 65504 once
    // the log-average divided them), -inf and negatives -> 0.
    vec3 g = mix(c, vec3(0.0), isnan(c));
    return clamp(g, 0.0, 1e38);
}

vec3 acesFitted(vec3 c) {
    const mat3 inputMat = mat3(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777);
    const mat3 outputMat = mat3(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602);
    vec3 v = inputMat * c;
    vec3 a = v * (v + 0.0245786) - 0.000090537;
    vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return clamp(outputMat * (a / b), 0.0, 1.0);
}

vec3 pbrNeutral(vec3 color) {
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression) return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}

void main() {
    vec3 hdr = guard(texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb);
    vec3 bloom = tonemap.bloom != 0 ? guard(texture(uBloom, vUv).rgb) : vec3(0.0);
    vec4 stats = texelFetch(uStats, ivec2(0), 0);
    int op = tonemap.toneOperator;
    // Exposure, and for the key-based operators the log-average normalisation.
    float scale = exp2(tonemap.exposure);
    if (op == TONEMAP_OPERATOR_REINHARD || tonemap.autoExposure != 0) scale *= tonemap.key / max(stats.x, 1e-9);
    hdr *= scale;
    bloom *= scale;
    if (tonemap.bloom != 0 && tonemap.bloomComposite == BLOOM_COMPOSITE_HDR_ADD) hdr += tonemap.bloomIntensity * bloom;
    vec3 rgb;
    if (op == TONEMAP_OPERATOR_ACES) {
        rgb = acesFitted(hdr);
    } else if (op == TONEMAP_OPERATOR_NEUTRAL) {
        rgb = clamp(pbrNeutral(hdr), 0.0, 1.0);
    } else if (op == TONEMAP_OPERATOR_CLAMP) {
        rgb = clamp(hdr, 0.0, 1.0);
    } else {
        float L = luminance(hdr);
        // Ld / L, formed without Ld itself (L * (1 + L / white^2) overflows
        // for L near the float limit) and capped, so hdr * ratio is never
        // 0 * infinity.
        float ratio;
        if (op == TONEMAP_OPERATOR_REINHARD) {
            // Auto white needs a brightest pixel: with none counted (or only
            // black ones) the manual white stands in.
            bool measured = stats.w > 0.5 && stats.y > 0.0;
            float white = tonemap.autoWhite != 0 && measured ? scale * stats.y : tonemap.white;
            white = max(white, 1e-6);
            ratio = (1.0 + L / (white * white)) / (1.0 + L);  // Ld = L (1 + L / white^2) / (1 + L)
        } else {
            ratio = 1.0 / (1.0 + L);  // Ld = L / (1 + L)
        }
        rgb = L > 0.0 ? clamp(hdr * min(ratio, 1e30), 0.0, 1.0) : vec3(0.0);
    }
    if (tonemap.bloom != 0 && tonemap.bloomComposite == BLOOM_COMPOSITE_LDR_LUMINANCE_ALPHA) {
        // Seed 002 step 10 / seed 004: the bloom, compressed like the image,
        // blended on top with alpha = its luminance.
        vec3 b = bloom / (1.0 + bloom);
        float a = clamp(luminance(b), 0.0, 1.0);
        rgb = clamp(rgb + tonemap.bloomIntensity * a * b, 0.0, 1.0);
    }
    outColor = vec4(tonemap.srgbOutput != 0 ? linearToSrgb(rgb) : rgb, 1.0);
}
