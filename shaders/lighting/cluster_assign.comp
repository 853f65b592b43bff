#version 450 core
// Clustered shading, step 2: one invocation per cluster tests every candidate
// light whose cluster range (worked out on the CPU, conservatively) holds the
// cluster against the cluster's volume: its tile's frustum between its
// surfaces' explicit depth bounds. In three stages, each a dispatch:
//   COUNT (once per slice uFirst .. uEnd of the candidates) adds the lights
//     the cluster takes to its count,
//   OFFSETS takes that many entries of the index list with one atomic add
//     and sets the count back to 0,
//   FILL (once per slice, in order) writes the slice's lights at the offset
//     plus the count so far, counting again;
// so the lights are in candidate order, and the shading sums in the same
// order every frame. The slices keep each invocation's loop under the
// driver's iteration limit (renderer/gl/ShaderLoopLimit.h), which a single
// pass over 32 768 candidates or more exceeded on llvmpipe. The list's
// capacity is the sum of the ranges' sizes, which no assignment can exceed.
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

// Per candidate: first and last tile across (x), down (y), slice (z), packed lo | hi << 16.
// (A buffer texture: see CandidateBuffers in renderer/lighting/LightLists.h.)
layout(binding = CLUSTER_RANGE_UNIT) uniform usamplerBuffer uRanges;

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
        cells[id].offset = cell.count > 0u ? atomicAdd(clusterLights.used, cell.count) : 0u;
        cells[id].count = 0u;
        return;
    }
    vec2 pixelMin = vec2(c.xy * uLayout.x);
    vec2 pixelMax = min(vec2((c.xy + 1) * uLayout.x), camera.viewport.xy);
    ScreenVolume volume = screenVolume(pixelMin, pixelMax, -uintBitsToFloat(cell.distMin), -uintBitsToFloat(cell.distMax));

    uint count = cell.count;
    for (int i = uFirst; i < uEnd; ++i) {
        uvec4 r = texelFetch(uRanges, i);
        if (!inRange(r.x, c.x) || !inRange(r.y, c.y) || !inRange(r.z, c.z)) continue;
        vec4 pr = candidatePositionRadius(i);
        if (!sphereMeetsVolume(volume, pr.xyz, pr.w)) continue;
        if (uStage == STAGE_COUNT) {
            ++count;
        } else if (cell.offset + count < uCapacity) {
            clusterLights.index[cell.offset + count] = uint(i);
            ++count;
        }
    }
    cells[id].count = count;
}
