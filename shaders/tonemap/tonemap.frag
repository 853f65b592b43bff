#version 450 core
// Tone mapping of the L-buffer to the displayable image (seed 000 sections
// 4.2 and 5.3; seed 002 step 9). Operators act on luminance and rescale RGB,
// which keeps chromaticity (the seed converts to XYZ and maps Y):
//   simple:   L_d = L / (1 + L)                                   (eq. 4.1)
//   reinhard: L = a / lum_log * L_w;
//             L_d = L (1 + L / L_white^2) / (1 + L)               (eqs. 4.3, 4.4)
// with lum_log and max(L_w) from the GPU reduction in luminance.stats.
#include "../common/color.glsl"
#include "../common/bindings.glsl"

#define OP_SIMPLE 0
#define OP_REINHARD 1

layout(binding = 0) uniform sampler2D uHdr;
layout(binding = 1) uniform sampler2D uStats;

layout(std140, binding = PASS_UBO) uniform TonemapParams {
    ivec4 modes;   // x operator, y auto white, z sRGB output
    vec4 values;   // x key a, y manual L_white, z exposure (EV)
} params;

in vec2 vUv;
out vec4 outColor;

void main() {
    vec3 hdr = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb;
    if (!isFiniteVec(hdr)) hdr = vec3(0.0);
    hdr = max(hdr, vec3(0.0)) * exp2(params.values.z);
    float Lw = luminance(hdr);
    float Ld;
    if (params.modes.x == OP_REINHARD) {
        vec4 stats = texelFetch(uStats, ivec2(0), 0);
        float scale = params.values.x / max(stats.x, 1e-9);
        float L = scale * Lw;
        float white = params.modes.y != 0 ? scale * stats.y * exp2(params.values.z) : params.values.y;
        white = max(white, 1e-6);
        Ld = L * (1.0 + L / (white * white)) / (1.0 + L);
    } else {
        Ld = Lw / (1.0 + Lw);
    }
    vec3 rgb = Lw > 0.0 ? hdr * (Ld / Lw) : vec3(0.0);
    rgb = clamp(rgb, 0.0, 1.0);
    outColor = vec4(params.modes.z != 0 ? linearToSrgb(rgb) : rgb, 1.0);
}
