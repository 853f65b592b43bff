#version 450 core
// GPU reduction of the L-buffer's luminance (seed 000 section 5.3.1): the
// first pass turns each output pixel (under SSAA the mean of its footprint)
// into (log(delta + L), L, L, 1) and sums per
// tile of LUMINANCE_TILE^2 pixels; later passes sum LUMINANCE_GROUP partials
// at a time; the last writes luminance.stats = (exp(mean log), max, mean, finite pixel count);
// with no pixel counted, or all of them black, the log-average is 1.
// Non-finite pixels are left out and do not poison the statistics; so are
// background pixels when luminance.background = exclude.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/color.glsl"
#include "../params/luminance.h"

layout(std430, binding = LUMINANCE_REDUCE_IN_SSBO) readonly buffer ReduceIn { vec4 inData[]; };
layout(std430, binding = LUMINANCE_REDUCE_OUT_SSBO) writeonly buffer ReduceOut { vec4 outData[]; };

vec4 combine(vec4 a, vec4 b) { return vec4(a.x + b.x, max(a.y, b.y), a.z + b.z, a.w + b.w); }

#if defined(FINALIZE)
layout(local_size_x = 1) in;
layout(rgba32f, binding = LUMINANCE_STATS_IMAGE) uniform writeonly image2D uStats;
void main() {
    vec4 s = inData[0];
    // Statistics of nothing: no pixel counted, or every counted pixel black.
    // The log-average falls back to 1 (a neutral exposure: key / 1, as with
    // no statistics at all) rather than delta, whose key / delta would
    // multiply every uncounted pixel (the excluded background) by ~2000.
    // The tone mapper reads count 0 or max 0 as "use the manual white".
    bool empty = s.w < 0.5 || s.y <= 0.0;
    float n = max(s.w, 1.0);
    imageStore(uStats, ivec2(0), vec4(empty ? 1.0 : exp(s.x / n), s.y, s.z / n, s.w));
}
#else
#if defined(FIRST_PASS)
layout(local_size_x = LUMINANCE_TILE, local_size_y = LUMINANCE_TILE) in;
layout(binding = LUMINANCE_HDR_TEXTURE) uniform sampler2D uHdr;
layout(binding = LUMINANCE_DEPTH_TEXTURE) uniform sampler2D uDepth;
#else
layout(local_size_x = LUMINANCE_GROUP) in;
#endif
shared vec4 partial[LUMINANCE_GROUP];

void main() {
    uint lid = gl_LocalInvocationIndex;
    vec4 v = vec4(0.0);
#if defined(FIRST_PASS)
    // One output pixel: under SSAA (footprint k > 1) the mean of its k x k
    // rendered pixels (those finite and, when excluded, not background),
    // the pixel's area mean as the reference's --spp N estimates it, so the
    // statistics (L_white above all) are the output image's, not those of
    // sub-pixel highlights; k = 1 is the pixel itself.
    int k = max(reduction.footprint, 1);
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(uHdr, 0) / k;
    if (px.x < size.x && px.y < size.y) {
        vec3 sum = vec3(0.0);
        int n = 0;
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i) {
                ivec2 q = px * k + ivec2(i, j);
                vec3 c = texelFetch(uHdr, q, 0).rgb;
                bool background = reduction.skipBackground != 0 && isFarDepth(texelFetch(uDepth, q, 0).r);
                if (isFiniteVec(c) && !background) {
                    sum += c;
                    ++n;
                }
            }
        if (n > 0) {
            float L = max(luminance(sum / float(n)), 0.0);
            v = vec4(log(reduction.delta + L), L, L, 1.0);
        }
    }
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
#else
    uint i = gl_GlobalInvocationID.x;
    if (i < uint(reduction.count)) v = inData[i];
    uint group = gl_WorkGroupID.x;
#endif
    partial[lid] = v;
    barrier();
    for (uint s = uint(LUMINANCE_GROUP) / 2u; s > 0u; s >>= 1u) {
        if (lid < s) partial[lid] = combine(partial[lid], partial[lid + s]);
        barrier();
    }
    if (lid == 0u) outData[group] = partial[0];
}
#endif
