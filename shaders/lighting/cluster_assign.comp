#version 450 core
// Clustered shading, step 2: one invocation per cluster tests every candidate
// light whose cluster range (worked out on the CPU, conservatively) holds the
// cluster against the cluster's volume: its tile's frustum between its
// surfaces' explicit depth bounds. It counts, takes that many entries of the
// index list with one atomic add, and writes the lights in candidate order,
// so the shading sums in the same order every frame. The list's capacity is
// the sum of the ranges' sizes, which no assignment can exceed.
#define CLUSTER_GRID_ACCESS restrict
#define CLUSTER_INDEX_ACCESS coherent
#include "../common/lighting.glsl"
#include "cluster_common.glsl"

layout(local_size_x = 64) in;

layout(location = 1) uniform int uCandidates;
layout(location = 7) uniform uint uCapacity;

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
    if (cell.distMin > cell.distMax) {
        cells[id].offset = 0u;
        cells[id].count = 0u;
        return;
    }
    vec2 pixelMin = vec2(c.xy * uLayout.x);
    vec2 pixelMax = min(vec2((c.xy + 1) * uLayout.x), camera.viewport.xy);
    ScreenVolume volume = screenVolume(pixelMin, pixelMax, -uintBitsToFloat(cell.distMin), -uintBitsToFloat(cell.distMax));

    uint count = 0u;
    for (int i = 0; i < uCandidates; ++i) {
        uvec4 r = texelFetch(uRanges, i);
        if (!inRange(r.x, c.x) || !inRange(r.y, c.y) || !inRange(r.z, c.z)) continue;
        vec4 pr = candidatePositionRadius(i);
        if (sphereMeetsVolume(volume, pr.xyz, pr.w)) ++count;
    }
    uint offset = count > 0u ? atomicAdd(clusterLights.used, count) : 0u;
    count = offset + count <= uCapacity ? count : (offset < uCapacity ? uCapacity - offset : 0u);
    uint k = 0u;
    for (int i = 0; i < uCandidates && k < count; ++i) {
        uvec4 r = texelFetch(uRanges, i);
        if (!inRange(r.x, c.x) || !inRange(r.y, c.y) || !inRange(r.z, c.z)) continue;
        vec4 pr = candidatePositionRadius(i);
        if (sphereMeetsVolume(volume, pr.xyz, pr.w)) clusterLights.index[offset + k++] = uint(i);
    }
    cells[id].offset = offset;
    cells[id].count = count;
}
