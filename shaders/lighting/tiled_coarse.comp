#version 450 core
// Tiled shading, coarse culling: the first level of a two-level tile
// hierarchy (as in Olsson and Assarsson 2011's hierarchical light grid; seed
// 003 section 2.2.1 for the tiles). One work group per coarse tile of
// COARSE x COARSE tiles of tiled.comp
//   1. finds the nearest and farthest depth of all its pixels that are not
//      cleared depth (tiled.comp also leaves out background pixels: a
//      coarse tile's range holds each of its tiles' ranges),
//   2. culls this dispatch's candidates (the same uFirst .. uEnd as
//      tiled.comp) against its frustum between those depths,
//   3. and writes the ones kept as a bit mask per coarse tile (WORDS words).
// tiled.comp then tests only its coarse tile's candidates, not all of them:
// at 10 000 lights a tile of 16 x 16 pixels tests a few hundred instead of
// 4096 per dispatch. The coarse volume holds every one of its tiles' volumes
// (its pixel rectangle holds theirs, its depth range theirs, so its box holds
// their boxes; in front of the eye its side planes' outside half-spaces
// hold theirs, and a sphere reaching behind the eye is tested against the
// box alone) and its test has more slack than theirs, so a light the finer
// test keeps is always in the mask and the tiles' lists are those of
// culling every candidate.
#include "gbuffer_read.glsl"
#include "tiles.glsl"

#ifndef TILE_THREADS
#define TILE_THREADS (TILE_SIZE * TILE_SIZE)
#endif
layout(local_size_x = TILE_THREADS) in;

layout(location = 1) uniform int uFirst;  // this dispatch's candidates: uFirst ..
layout(location = 2) uniform int uEnd;    // .. uEnd, at most MAX_CANDIDATES

#define WORDS (MAX_CANDIDATES / 32)
#define COARSE_PIXELS (COARSE * TILE_SIZE)

// Per coarse tile (row-major over the coarse grid), WORDS words of bits:
// bit b of word w set when candidate uFirst + 32 w + b may meet one of the
// coarse tile's tiles.
layout(std430, binding = TILE_COARSE_MASK_SSBO) writeonly buffer TileCoarseMask {
    uint coarseMask[];
};

shared uint sDepthMin, sDepthMax;
shared uint sMask[WORDS];

void main() {
    ivec2 size = ivec2(camera.viewport.xy);
    uint tid = gl_LocalInvocationIndex;
    if (tid == 0u) {
        sDepthMin = 0xFFFFFFFFu;
        sDepthMax = 0u;
    }
    for (uint w = tid; w < uint(WORDS); w += uint(TILE_THREADS)) sMask[w] = 0u;
    barrier();

    ivec2 tileMin = ivec2(gl_WorkGroupID.xy) * COARSE_PIXELS;
    ivec2 tileMax = min(tileMin + COARSE_PIXELS, size);
    // Depths are >= 0, so their bit patterns order like the values.
    uint depthMin = 0xFFFFFFFFu, depthMax = 0u;
    for (uint p = tid; p < uint(COARSE_PIXELS * COARSE_PIXELS); p += uint(TILE_THREADS)) {
        ivec2 px = tileMin + ivec2(p % uint(COARSE_PIXELS), p / uint(COARSE_PIXELS));
        if (any(greaterThanEqual(px, tileMax))) continue;
        float depth = texelFetch(uDepth, px, 0).r;
        if (isFarDepth(depth)) continue;
        depthMin = min(depthMin, floatBitsToUint(depth));
        depthMax = max(depthMax, floatBitsToUint(depth));
    }
    if (depthMin <= depthMax) {
        atomicMin(sDepthMin, depthMin);
        atomicMax(sDepthMax, depthMax);
    }
    barrier();

    if (sDepthMin <= sDepthMax) {
        // As tiled.comp: view-space z depends on the depth only, so the
        // coarse bounds hold the tiles' bounds whatever pixel they are taken at.
        vec2 pixelMin = vec2(tileMin), pixelMax = vec2(tileMax);
        vec2 centreUv = 0.5 * (pixelMin + pixelMax) * camera.viewport.zw;
        float z0 = viewPositionFromDepth(centreUv, uintBitsToFloat(sDepthMin)).z;
        float z1 = viewPositionFromDepth(centreUv, uintBitsToFloat(sDepthMax)).z;
        ScreenVolume volume = screenVolume(pixelMin, pixelMax, max(z0, z1), min(z0, z1));
        for (int i = uFirst + int(tid); i < uEnd; i += TILE_THREADS) {
            vec4 pr = candidatePositionRadius(i);
            // Ten times tiled.comp's slack for rounding on top of its own.
            float r = pr.w * 1.001 + 1e-4;
            // The side planes of a perspective view pass through the eye. In
            // front of it (z < 0) the coarse tile's outside half-spaces hold
            // its tiles'; behind it they do not, so a sphere reaching behind
            // the eye could lie outside a coarse plane and still be kept by a
            // tile (by the box around the tile's slab, which holds points of
            // neither frustum). Such a sphere is tested against the coarse box
            // alone, which holds every tile's box.
            bool keep = pr.z + r * 1.0001 + 1e-5 >= 0.0 ? sphereMeetsBox(volume, pr.xyz, r * 1.0001 + 1e-5)
                                                        : sphereMeetsVolume(volume, pr.xyz, r);
            if (keep) atomicOr(sMask[(i - uFirst) >> 5], 1u << ((i - uFirst) & 31));
        }
    }
    barrier();

    uint base = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * uint(WORDS);
    for (uint w = tid; w < uint(WORDS); w += uint(TILE_THREADS)) coarseMask[base + w] = sMask[w];
}
