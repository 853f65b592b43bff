#version 450 core
// The transparent layers of a pixel, composited: the output is (C, T), the
// layers' premultiplied colour blended back to front with "over",
// C = a_i C_i + (1 - a_i) C (seed 000 eq. 3.6 with the operands in this
// order), and their transmittance T = prod(1 - a_i); the pass blends it over
// the L-buffer as L = C + T L (GL_ONE, GL_SRC_ALPHA). One variant per method:
//   RESOLVE_ABUFFER: every sample of the stencil-routed A-buffer (seed 000
//     section 5.9), sorted by depth; the fragments past the samples counted
//     into oit.overflow (oit.sample_count - samples).
//   RESOLVE_LIST: the pixel's linked list, the nearest OIT_LIST_MAX_FRAGMENTS
//     kept in a local array and sorted; the rest counted into oit.overflow
//     (oit.sample_count - kept).
//   RESOLVE_WEIGHTED: McGuire and Bavoil 2013's composite (their eq. 6).
//   RESOLVE_DUAL: dual depth peeling's front layers over its back layers;
//   RESOLVE_PEEL: the layers depth peeling accumulated front to back;
//     the fragments past the peeled layers counted into oit.overflow.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../params/oit.h"

layout(location = 0) out vec4 outColor;
layout(binding = OIT_FRAGMENT_COUNT_IMAGE, r32ui) uniform coherent uimage2D uFragmentCount;  // oit.sample_count
layout(binding = OIT_OVERFLOW_IMAGE, r32ui) uniform coherent uimage2D uLost;           // oit.overflow
// The frame's fragments lost and arrived, summed over the pixels: the pass
// reads them back for its one-line warning (OitPass::frameWarning).
layout(std430, binding = OIT_LOST_TOTAL_SSBO) buffer LostTotal { uint lostTotal; uint arrivedTotal; };

// Stores a pixel's lost fragments into oit.overflow and adds them to the totals.
void countLost(ivec2 px, uint arrived, uint lost) {
    imageStore(uLost, px, uvec4(lost));
    if (arrived > 0u) atomicAdd(arrivedTotal, arrived);
    if (lost > 0u) atomicAdd(lostTotal, lost);
}

bool farther(float a, float b) { return depthReversed() ? a < b : a > b; }

#if defined(RESOLVE_ABUFFER)
layout(binding = OIT_SAMPLES_TEXTURE) uniform sampler2DMS uSamples;
layout(binding = OIT_SAMPLE_DEPTH_TEXTURE) uniform sampler2DMS uSampleDepth;
#elif defined(RESOLVE_LIST)
layout(binding = OIT_LIST_HEADS_IMAGE, r32ui) uniform coherent uimage2D uHeads;
layout(std430, binding = OIT_LIST_NODES_SSBO) readonly buffer ListNodes { uint nodeWords[]; };  // OIT_LIST_NODE_WORDS a node
#elif defined(RESOLVE_WEIGHTED)
layout(binding = OIT_ACCUM_TEXTURE) uniform sampler2D uAccum;
layout(binding = OIT_REVEALAGE_TEXTURE) uniform sampler2D uRevealage;
#elif defined(RESOLVE_PEEL)
layout(binding = OIT_PEEL_ACCUM_TEXTURE) uniform sampler2D uPeelAccum;  // (C, T) front to back
layout(binding = OIT_PEEL_LAYERS_IMAGE, r32ui) uniform coherent uimage2D uLayers;  // oit.peel_layers
#elif defined(RESOLVE_DUAL)
layout(binding = OIT_FRONT_ACCUM_TEXTURE) uniform sampler2D uFrontAccum;  // (C, T) of the front layers, front to back
layout(binding = OIT_BACK_ACCUM_TEXTURE) uniform sampler2D uBackAccum;   // (C, T) of the back layers, back to front
layout(binding = OIT_PEEL_LAYERS_IMAGE, r32ui) uniform coherent uimage2D uLayers;
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
#if defined(RESOLVE_ABUFFER) || defined(RESOLVE_LIST)
#if defined(RESOLVE_ABUFFER)
    const int kMax = OIT_MAX_SAMPLES;
#else
    const int kMax = OIT_LIST_MAX_FRAGMENTS;
#endif
    vec4 colour[kMax];
    float depth[kMax];
    int n = 0;
#if defined(RESOLVE_ABUFFER)
    uint arrived = imageLoad(uFragmentCount, px).r;
    n = int(min(arrived, uint(oit.samples)));
    countLost(px, arrived, arrived - uint(n));
    for (int i = 0; i < n; ++i) {
        colour[i] = texelFetch(uSamples, px, i);
        depth[i] = texelFetch(uSampleDepth, px, i).r;
    }
#else
    // Links are node index + 1, 0 ending the list: a lane whose loads are
    // masked (llvmpipe returns 0 for them) stops instead of walking node 0's
    // list until the driver's loop limit (2.5 s a frame at 320x180).
    // The walk reads at most oit.walkLimit nodes (0: all): the driver ends a
    // shader's loops silently past its iteration budget, so the bound keeps
    // the walk, the sort and the blend inside it. What is not kept (over the
    // node budget, past the kMax nearest, past the walk's bound) is
    // oit.sample_count - kept, every fragment having been counted.
    uint link = imageLoad(uHeads, px).r;
    uint walked = 0u;
    int far = 0;  // the farthest kept, once the array is full
    while (link != 0u && (oit.walkLimit == 0u || walked < oit.walkLimit)) {
        uint at = (link - 1u) * uint(OIT_LIST_NODE_WORDS);
        vec4 c = vec4(uintBitsToFloat(nodeWords[at]), uintBitsToFloat(nodeWords[at + 1u]),
                      uintBitsToFloat(nodeWords[at + 2u]), uintBitsToFloat(nodeWords[at + 3u]));
        float z = uintBitsToFloat(nodeWords[at + 4u]);
        link = nodeWords[at + 5u];
        ++walked;
        if (n < kMax) {
            colour[n] = c;
            depth[n] = z;
            if (n == 0 || farther(z, depth[far])) far = n;
            ++n;
        } else if (farther(depth[far], z)) {
            // Full: keep the nearest kMax; the farthest makes room, then the new farthest is found.
            colour[far] = c;
            depth[far] = z;
            far = 0;
            for (int i = 1; i < kMax; ++i)
                if (farther(depth[i], depth[far])) far = i;
        }
    }
    uint arrived = imageLoad(uFragmentCount, px).r;
    countLost(px, arrived, arrived > uint(n) ? arrived - uint(n) : 0u);
#endif
    if (n == 0) discard;
    // Insertion sort, farthest first.
    for (int i = 1; i < n; ++i) {
        vec4 c = colour[i];
        float z = depth[i];
        int j = i - 1;
        while (j >= 0 && farther(z, depth[j])) {
            colour[j + 1] = colour[j];
            depth[j + 1] = depth[j];
            --j;
        }
        colour[j + 1] = c;
        depth[j + 1] = z;
    }
    vec3 C = vec3(0.0);
    float T = 1.0;
    for (int i = 0; i < n; ++i) {
        C = colour[i].rgb + (1.0 - colour[i].a) * C;
        T *= 1.0 - colour[i].a;
    }
    outColor = vec4(C, T);
#elif defined(RESOLVE_WEIGHTED)
    vec4 accum = texelFetch(uAccum, px, 0);
    float revealage = texelFetch(uRevealage, px, 0).r;
    if (revealage >= 1.0) discard;  // nothing transparent here
    // RGBA32F accumulation: no upper clamp (the paper's 5e4 guarded RGBA16F).
    vec3 average = accum.rgb / max(accum.a, 1e-4);
    outColor = vec4(average * (1.0 - revealage), revealage);
#elif defined(RESOLVE_PEEL)
    uint arrived = imageLoad(uFragmentCount, px).r;
    uint layers = imageLoad(uLayers, px).r;
    countLost(px, arrived, arrived > layers ? arrived - layers : 0u);
    if (layers == 0u) discard;
    outColor = texelFetch(uPeelAccum, px, 0);
#elif defined(RESOLVE_DUAL)
    uint arrived = imageLoad(uFragmentCount, px).r;
    uint layers = imageLoad(uLayers, px).r;
    countLost(px, arrived, arrived > layers ? arrived - layers : 0u);
    if (layers == 0u) discard;
    vec4 front = texelFetch(uFrontAccum, px, 0), back = texelFetch(uBackAccum, px, 0);
    outColor = vec4(front.rgb + front.a * back.rgb, front.a * back.a);
#endif
}
