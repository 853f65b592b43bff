#version 450 core
// lighting.cluster_counts: the length of each surface pixel's cluster list
// (lights with a shadow map included), 0 on the background.
#include "../common/bindings.glsl"
#define CLUSTER_GRID_ACCESS readonly
#define CLUSTER_INDEX_ACCESS readonly
#include "gbuffer_read.glsl"
#include "cluster_common.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = CLUSTER_COUNTS_IMAGE, r32f) uniform restrict writeonly image2D uClusterCounts;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, ivec2(camera.viewport.xy)))) return;
    float depth = texelFetch(uDepth, px, 0).r;
    float type = floor(texelFetch(uAlbedo, px, 0).a * 255.0 + 0.5);
    float count = 0.0;
    if (!(isFarDepth(depth) || type == PIXEL_BACKGROUND))
        count = float(cells[pixelCluster(px, -viewPositionAtPixel(px, depth).z)].count);
    imageStore(uClusterCounts, px, vec4(count));
}
