// The cluster grid of the clustered strategy (Olsson, Billeter and Assarsson
// 2012): per cluster its surfaces' nearest and farthest distance (the
// explicit bounds of the paper's section 4.4) and its slice of the light
// index list; the list holds indices into candidateRows.
#ifndef CLUSTER_COMMON_GLSL
#define CLUSTER_COMMON_GLSL
#include "tiles.glsl"

layout(location = 4) uniform ivec2 uTiles;    // tiles across and down
layout(location = 5) uniform ivec2 uLayout;   // tile size in pixels, depth slices
layout(location = 6) uniform vec2 uSlicing;   // near, slices / log(far / near)

struct ClusterCell {
    uint distMin, distMax;  // float bits of the distance along -z (min > max: no surface)
    uint offset, count;     // into clusterLights.index[1 ..]
};

layout(std430, binding = CLUSTER_GRID_SSBO) CLUSTER_GRID_ACCESS buffer ClusterGrid {
    ClusterCell cells[];
};

layout(std430, binding = CLUSTER_INDEX_SSBO) CLUSTER_INDEX_ACCESS buffer ClusterLights {
    uint used;  // entries handed out so far
    uint index[];
} clusterLights;

uint pixelCluster(ivec2 px, float dist) {
    return clusterIndex(px, dist, uTiles, uLayout.x, uSlicing, uLayout.y);
}

#endif
