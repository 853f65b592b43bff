#version 450 core
// Clustered shading, step 2: one invocation per cluster tests every candidate
// light whose cluster range (worked out on the CPU, conservatively) holds the
// cluster against the cluster's volume: its tile's frustum between its
// surfaces' explicit depth bounds. In three stages, each a dispatch:
//   COUNT (once per slice uFirst .. uEnd of the candidates) adds the lights
//     the cluster takes to its count,
//   OFFSETS takes that many entries of the index list with one atomic add,
//   FILL (once per slice, in order) writes the slice's lights at the offset
//     plus how many it wrote before (its entry of ClusterFill), stopping
//     once it has written the count;
// so the lights are in candidate order, and the shading sums in the same
// order every frame. The slices keep each invocation's loop under the
// driver's iteration limit (renderer/gl/ShaderLoopLimit.h), which a single
// pass over 32 768 candidates or more exceeded on llvmpipe. The list's
// capacity is the sum of the ranges' sizes, which no assignment can exceed.
#include "../common/bindings.glsl"
#define CLUSTER_GRID_ACCESS restrict
#define CLUSTER_INDEX_ACCESS coherent
#include "../common/lighting.glsl"
#include "cluster_common.glsl"

layout(local_size_x = 64) in;

layout(location = 1) uniform int uFirst;  // this dispatch's candidates: uFirst ..
layout(location = 2) uniform int uEnd;    // .. uEnd (COUNT and FILL)
layout(location = 3) uniform int uStage;
layout(location = 7) uniform uint uCapacity;

#define STAGE_COUNT 0
#define STAGE_OFFSETS 1
#define STAGE_FILL 2

// Per cluster, the entries FILL has written so far (cleared to 0 by the CPU).
layout(std430, binding = CLUSTER_FILL_SSBO) restrict buffer ClusterFill {
    uint filled[];
};

// Per candidate: first and last tile across (x), down (y), slice (z), packed lo | hi << 16.
// (A buffer texture: see CandidateBuffers in renderer/lighting/LightLists.h.)
layout(binding = CLUSTER_RANGE_TEXTURE) uniform usamplerBuffer uRanges;

bool inRange(uint span, int v) {
    return v >= int(span & 0xFFFFu) && v <= int(span >> 16);
}

void main() {
    // x: the tile within the slice, y: the slice (keeps the group count per
    // dimension small whatever the grid).
    int perSlice = uTiles.x * uTiles.y;
    int tileIndex = int(gl_GlobalInvocationID.x);
    if (tileIndex >= perSlice) return;
    ivec3 c = ivec3(tileIndex % uTiles.x, tileIndex / uTiles.x, int(gl_GlobalInvocationID.y));
    uint id = uint(c.z * perSlice + tileIndex);
    ClusterCell cell = cells[id];
    // No surface: count and offset stay 0, as the grid was cleared.
    if (cell.distMin > cell.distMax) return;
    if (uStage == STAGE_OFFSETS) {
        uint offset = cell.count > 0u ? atomicAdd(clusterLights.used, cell.count) : 0u;
        cells[id].offset = offset;
        // Never past the list's end (the capacity bounds every assignment; this only guards it).
        cells[id].count = offset + cell.count <= uCapacity ? cell.count : (offset < uCapacity ? uCapacity - offset : 0u);
        return;
    }
    if (uStage == STAGE_FILL && filled[id] >= cell.count) return;
    vec2 pixelMin = vec2(c.xy * uLayout.x);
    vec2 pixelMax = min(vec2((c.xy + 1) * uLayout.x), camera.viewport.xy);
    ScreenVolume volume = screenVolume(pixelMin, pixelMax, -uintBitsToFloat(cell.distMin), -uintBitsToFloat(cell.distMax));

    if (uStage == STAGE_COUNT) {
        uint count = cell.count;
        for (int i = uFirst; i < uEnd; ++i) {
            uvec4 r = texelFetch(uRanges, i);
            if (!inRange(r.x, c.x) || !inRange(r.y, c.y) || !inRange(r.z, c.z)) continue;
            vec4 pr = candidatePositionRadius(i);
            if (sphereMeetsVolume(volume, pr.xyz, pr.w)) ++count;
        }
        cells[id].count = count;
    } else {
        uint k = filled[id];
        for (int i = uFirst; i < uEnd && k < cell.count; ++i) {
            uvec4 r = texelFetch(uRanges, i);
            if (!inRange(r.x, c.x) || !inRange(r.y, c.y) || !inRange(r.z, c.z)) continue;
            vec4 pr = candidatePositionRadius(i);
            if (sphereMeetsVolume(volume, pr.xyz, pr.w)) clusterLights.index[cell.offset + k++] = uint(i);
        }
        filled[id] = k;
    }
}
