#version 450 core
// Clustered shading, step 1: each surface pixel widens its cluster's explicit
// depth bounds (the clusters that hold no surface stay empty and get no lights).
#define CLUSTER_GRID_ACCESS coherent
#define CLUSTER_INDEX_ACCESS readonly
#include "gbuffer_read.glsl"
#include "cluster_common.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, ivec2(camera.viewport.xy)))) return;
    float depth = texelFetch(uDepth, px, 0).r;
    float type = floor(texelFetch(uAlbedo, px, 0).a * 255.0 + 0.5);
    if (isFarDepth(depth) || type == PIXEL_BACKGROUND) return;
    float dist = -viewPositionAtPixel(px, depth).z;
    uint c = pixelCluster(px, dist);
    atomicMin(cells[c].distMin, floatBitsToUint(dist));
    atomicMax(cells[c].distMax, floatBitsToUint(dist));
}
