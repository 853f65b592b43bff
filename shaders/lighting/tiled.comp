#version 450 core
// Tiled deferred shading (seed 003 section 2.2.1, seed 004 "Moving forward"):
// one work group per TILE_SIZE x TILE_SIZE screen tile finds its surfaces'
// nearest and farthest depth, culls the candidate lights' bounding spheres
// against the tile's frustum between them into a list in shared memory, then
// every pixel adds the list's lights whose sphere holds its surface (the same lightRadiance as
// light.frag) into the L-buffer with one read-modify-write.
// The list is a bit mask over up to MAX_CANDIDATES candidates (the CPU
// dispatches again for the next ones), walked in candidate order, so the sum
// is the same every frame whatever the threads' timing. The shading loop
// comes after the last barrier: llvmpipe turns barriers into coroutine
// splits, and values live across one cost a trip through memory.
// Shaded lights never have a shadow map (those go one at a time).
#define UNSHADOWED 1
#include "shade.glsl"
#include "tiles.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

layout(binding = 0, rgba32f) uniform restrict image2D uLBuffer;
layout(binding = 1, r32f) uniform restrict image2D uOverlap;     // when FLAG_COUNT_OVERLAP
layout(binding = 2, r32f) uniform restrict image2D uTileCounts;  // when FLAG_TILE_COUNTS

layout(location = 1) uniform int uFirst;   // this dispatch's candidates: candidateRows[uFirst ..
layout(location = 2) uniform int uEnd;     // .. uEnd), at most MAX_CANDIDATES
layout(location = 3) uniform int uShaded;  // candidates below this index are shaded, the rest only counted
layout(location = 4) uniform int uFlags;

#define FLAG_SHADE 1
#define FLAG_COUNT_OVERLAP 2
#define FLAG_TILE_COUNTS 4
#define FLAG_ADD_COUNTS 8  // not the first dispatch: add to the tile counts

#define MAX_CANDIDATES 4096
#define GROUP_SIZE (TILE_SIZE * TILE_SIZE)

shared uint sDepthMin, sDepthMax;
shared uint sMask[MAX_CANDIDATES / 32];

bool surfaceAt(ivec2 px, out float depth) {
    depth = texelFetch(uDepth, px, 0).r;
    float type = floor(texelFetch(uAlbedo, px, 0).a * 255.0 + 0.5);
    return !(isFarDepth(depth) || type == PIXEL_BACKGROUND);
}

void main() {
    ivec2 size = ivec2(camera.viewport.xy);
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    uint tid = gl_LocalInvocationIndex;
    bool inImage = all(lessThan(px, size));
    if (tid == 0u) {
        sDepthMin = 0xFFFFFFFFu;
        sDepthMax = 0u;
    }
    for (uint w = tid; w < uint(MAX_CANDIDATES / 32); w += uint(GROUP_SIZE)) sMask[w] = 0u;
    barrier();

    float depth;
    // Depths are >= 0, so their bit patterns order like the values.
    if (inImage && surfaceAt(px, depth)) {
        atomicMin(sDepthMin, floatBitsToUint(depth));
        atomicMax(sDepthMax, floatBitsToUint(depth));
    }
    barrier();

    if (sDepthMin <= sDepthMax) {
        ivec2 tileMin = ivec2(gl_WorkGroupID.xy) * TILE_SIZE;
        vec2 pixelMin = vec2(tileMin), pixelMax = vec2(min(tileMin + TILE_SIZE, size));
        vec2 centreUv = 0.5 * (pixelMin + pixelMax) * camera.viewport.zw;
        // Which extreme is nearer depends on the depth convention (reversed: the largest).
        float z0 = viewPositionFromDepth(centreUv, uintBitsToFloat(sDepthMin)).z;
        float z1 = viewPositionFromDepth(centreUv, uintBitsToFloat(sDepthMax)).z;
        float zNear = max(z0, z1), zFar = min(z0, z1);
        ScreenVolume volume = screenVolume(pixelMin, pixelMax, zNear, zFar);
        for (int i = uFirst + int(tid); i < uEnd; i += GROUP_SIZE) {
            vec4 pr = lights[candidateRows[i]].positionRadius;
            if (sphereMeetsVolume(volume, pr.xyz, pr.w)) atomicOr(sMask[(i - uFirst) >> 5], 1u << ((i - uFirst) & 31));
        }
    }
    barrier();

    if (!inImage) return;
    uint words = uint(uEnd - uFirst + 31) / 32u;
    uint tileLights = 0u;
    for (uint w = 0u; w < words; ++w) tileLights += uint(bitCount(sMask[w]));

    uint shaded = 0u;
    if ((uFlags & FLAG_SHADE) != 0 && tileLights > 0u) {
        Surface s = readSurface(px);
        if (isSurface(s)) {
            vec3 sum = vec3(0.0);
            for (uint w = 0u; w < words; ++w) {
                uint bits = sMask[w];
                while (bits != 0u) {
                    int i = uFirst + int(w) * 32 + findLSB(bits);
                    bits &= bits - 1u;
                    if (i >= uShaded) break;  // candidates are in order: the rest are only counted
                    uint row = candidateRows[i];
                    if (!lightReaches(row, s.position)) continue;
                    sum += lightRadiance(lights[row], s);
                    ++shaded;
                }
            }
            // Each pixel belongs to one invocation, and the L-buffer's earlier
            // writes (ambient, directional lights) came through the
            // framebuffer before this dispatch.
            if (shaded > 0u) imageStore(uLBuffer, px, imageLoad(uLBuffer, px) + vec4(sum, 0.0));
        }
    }
    if ((uFlags & FLAG_COUNT_OVERLAP) != 0) imageStore(uOverlap, px, imageLoad(uOverlap, px) + vec4(float(shaded)));
    if ((uFlags & FLAG_TILE_COUNTS) != 0) {
        float before = (uFlags & FLAG_ADD_COUNTS) != 0 ? imageLoad(uTileCounts, px).r : 0.0;
        imageStore(uTileCounts, px, vec4(before + float(tileLights)));
    }
}
