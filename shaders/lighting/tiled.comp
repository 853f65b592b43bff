#version 450 core
// Tiled deferred shading (seed 003 section 2.2.1, seed 004 "Moving forward";
// Andersson 2009, Olsson and Assarsson 2011): one work group per
// TILE_SIZE x TILE_SIZE screen tile
//   1. finds its surfaces' nearest and farthest depth,
//   2. culls the candidate lights' bounding spheres against the tile's
//      frustum between those depths into a bit list in shared memory (with
//      lighting.tile_coarse only the candidates its coarse tile kept:
//      tiled_coarse.comp); with
//      DEPTH_MASK (lighting.tile_depth_mask) a light must also span one of
//      the 32 depth slices between them that holds a surface (2.5D culling,
//      Harada 2012), which drops the lights that fall in a depth gap,
//   3. turns the bit list into a list of candidate indices in shared memory
//      (in candidate order),
//   4. and every pixel walks that list and adds the lights that reach its
//      surface (candidateReaches: the radius and cone tests of light.frag's
//      lightRadiance; then lightRadianceAt, with each pixel's view
//      direction computed once) into the L-buffer. With
//      lighting.tile_ambient the first dispatch (FLAG_FIRST) also writes
//      each pixel's first radiance (ambient.glsl: ambient, emission, the
//      sky) with one store, and no full-screen ambient pass runs before
//      (Andersson 2009); otherwise, and in later dispatches, it adds with
//      one read-modify-write. An invocation with several pixels walks the
//      list for WALK of them at once. With TILE_WALK_MARK
//      (lighting.tile_walk, by default on a CPU rasteriser) it takes the
//      list 32 lights at a time: first it marks which of the 32 reach one
//      of its WALK pixels (one light's position and cone fetched once for
//      all of them), then it shades only the marked ones. On a CPU
//      rasteriser a branch does not skip its body for lanes that all fail
//      it (the body runs under a mask), but a loop stops when its last lane
//      is done, so the shading loop costs the marked lights alone, not the
//      whole list (lighting pass at 10 000 lights, 640x360: docs/bench.md).
//      Otherwise (by default on a GPU, where a group's lanes skip a branch
//      together) it tests and shades each listed light in turn.
// Light data comes from the candidates' buffer texture (tiles.glsl). On
// llvmpipe walking the index list costs a third of walking the bits with
// findLSB (lighting pass at 1000 lights, 640x360: docs/bench.md).
// The group has TILE_THREADS invocations, each shading every
// TILE_THREADS-th pixel of the tile (lighting.tile_threads): one per pixel
// suits a GPU; on a CPU rasteriser, which runs a group's SIMD batches as
// coroutines switched at every barrier, one SIMD batch per tile costs far less.
// The bit list covers up to MAX_CANDIDATES candidates (the CPU dispatches
// again for the next ones) and is walked in candidate order, so the sum is
// the same every frame whatever the threads' timing.
// Shaded lights never have a shadow map (those go one at a time).
#include "../common/bindings.glsl"
#define UNSHADOWED 1
#include "shade.glsl"
#include "ambient.glsl"
#include "tiles.glsl"

#ifndef TILE_THREADS
#define TILE_THREADS (TILE_SIZE * TILE_SIZE)
#endif
layout(local_size_x = TILE_THREADS) in;

layout(binding = TILED_LBUFFER_IMAGE, rgba32f) uniform restrict image2D uLBuffer;
layout(binding = TILED_OVERLAP_IMAGE, r32f) uniform restrict image2D uOverlap;     // when FLAG_COUNT_OVERLAP
layout(binding = TILED_COUNTS_IMAGE, r32f) uniform restrict image2D uTileCounts;  // when FLAG_TILE_COUNTS

#ifdef COARSE
// The coarse tiles' candidate masks, written by tiled_coarse.comp just before.
layout(std430, binding = TILE_COARSE_MASK_SSBO) readonly buffer TileCoarseMask {
    uint coarseMask[];
};
#endif

layout(location = 1) uniform int uFirst;   // this dispatch's candidates: candidateRows[uFirst ..
layout(location = 2) uniform int uEnd;     // .. uEnd), at most MAX_CANDIDATES
layout(location = 3) uniform int uShaded;  // candidates below this index are shaded, the rest only counted
layout(location = 4) uniform int uFlags;

#define FLAG_SHADE 1
#define FLAG_COUNT_OVERLAP 2
#define FLAG_TILE_COUNTS 4
#define FLAG_ADD_COUNTS 8  // not the first dispatch: add to the tile counts
#define FLAG_FIRST 16      // write firstRadiance plus the lights, no read (lighting.tile_ambient)

// MAX_CANDIDATES (the most candidates of one dispatch: the bits' size) and
// COARSE (tiles per coarse tile edge, when lighting.tile_coarse) come from
// TiledStrategy.cpp.
#define WORDS (MAX_CANDIDATES / 32)
#define TILE_PIXELS (TILE_SIZE * TILE_SIZE)
#define PIXELS_PER_THREAD ((TILE_PIXELS + TILE_THREADS - 1) / TILE_THREADS)
// WALK, pixels per walk of the list, comes from TiledStrategy.cpp too
// (4 measured best on llvmpipe, docs/bench.md; fewer with fewer pixels):
// the number of walks bounds the candidates per dispatch there.

shared uint sDepthMin, sDepthMax;
shared uint sDepthSlices;  // DEPTH_MASK: bit k set when slice k holds a surface
shared uint sMask[WORDS];
shared uint sBefore[WORDS];         // listed lights in the words before
shared uint sListed;                // listed lights
shared uint sShadedListed;          // of them, those below uShaded (they come first)
shared uint sList[MAX_CANDIDATES];  // the listed candidates' indices

// The depth slice (0 to 31) of view-space z in a tile whose nearest surface
// is at zNear, sliceScale = 32 / (zNear - zFar).
uint depthSlice(float z, float zNear, float sliceScale) {
    return uint(clamp((zNear - z) * sliceScale, 0.0, 31.0));
}

ivec2 tilePixel(uint k) {
    uint p = gl_LocalInvocationIndex + k * uint(TILE_THREADS);
    return ivec2(gl_WorkGroupID.xy) * TILE_SIZE + ivec2(p % uint(TILE_SIZE), p / uint(TILE_SIZE));
}

bool pixelInTile(uint k, ivec2 size) {
    return gl_LocalInvocationIndex + k * uint(TILE_THREADS) < uint(TILE_PIXELS) &&
           all(lessThan(tilePixel(k), size));
}

// Writes a pixel's sum into the L-buffer (on top of its first radiance in
// the first dispatch, else added to what is there) and its counts. Each
// pixel belongs to one invocation.
void writePixel(ivec2 px, Surface s, vec3 sum, uint shaded, uint tileLights) {
    if ((uFlags & FLAG_FIRST) != 0) imageStore(uLBuffer, px, vec4(firstRadiance(px, s) + sum, 1.0));
    else if (shaded > 0u) imageStore(uLBuffer, px, imageLoad(uLBuffer, px) + vec4(sum, 0.0));
    if ((uFlags & FLAG_COUNT_OVERLAP) != 0) imageStore(uOverlap, px, imageLoad(uOverlap, px) + vec4(float(shaded)));
    if ((uFlags & FLAG_TILE_COUNTS) != 0) {
        float before = (uFlags & FLAG_ADD_COUNTS) != 0 ? imageLoad(uTileCounts, px).r : 0.0;
        imageStore(uTileCounts, px, vec4(before + float(tileLights)));
    }
}

// The slack of the marking's test (relative on the radius, absolute on the
// cone's cosine): far above the roundings by which two copies of the same
// test could differ, far below a light's extent.
#define MARK_SLACK 1e-4

// Whether candidate light i reaches each lit pixel of the walk (the exact
// test), and if so adds its radiance and counts it.
void shadeListed(int i, Surface surf[WALK], bool lit[WALK], vec3 V[WALK], inout vec3 sum[WALK],
                 inout uint shaded[WALK]) {
    Light light = candidateLight(i);
    for (int j = 0; j < WALK; ++j) {
        float d;
        vec3 L;
        if (lit[j] && candidateReaches(light.positionRadius, light.directionCutoff, surf[j].position, 0.0, d, L)) {
            sum[j] += lightRadianceAt(light, surf[j], L, d, V[j]);
            ++shaded[j];
        }
    }
}

void main() {
    ivec2 size = ivec2(camera.viewport.xy);
    uint tid = gl_LocalInvocationIndex;
    if (tid == 0u) {
        sDepthMin = 0xFFFFFFFFu;
        sDepthMax = 0u;
        sDepthSlices = 0u;
    }
    for (uint w = tid; w < uint(WORDS); w += uint(TILE_THREADS)) sMask[w] = 0u;
    barrier();

    // 1. Depths are >= 0, so their bit patterns order like the values.
    uint depthMin = 0xFFFFFFFFu, depthMax = 0u;
    for (uint k = 0u; k < uint(PIXELS_PER_THREAD); ++k) {
        if (!pixelInTile(k, size)) continue;
        ivec2 px = tilePixel(k);
        float depth = texelFetch(uDepth, px, 0).r;
        float type = floor(texelFetch(uAlbedo, px, 0).a * 255.0 + 0.5);
        if (isFarDepth(depth) || type == PIXEL_BACKGROUND) continue;
        depthMin = min(depthMin, floatBitsToUint(depth));
        depthMax = max(depthMax, floatBitsToUint(depth));
    }
    if (depthMin <= depthMax) {
        atomicMin(sDepthMin, depthMin);
        atomicMax(sDepthMax, depthMax);
    }
    barrier();

    // 2. The tile's frustum between its nearest and farthest surface.
    bool tileHasSurface = sDepthMin <= sDepthMax;
    ivec2 tileMin = ivec2(gl_WorkGroupID.xy) * TILE_SIZE;
    vec2 pixelMin = vec2(tileMin), pixelMax = vec2(min(tileMin + TILE_SIZE, size));
    vec2 centreUv = 0.5 * (pixelMin + pixelMax) * camera.viewport.zw;
    // Which extreme is nearer depends on the depth convention (reversed: the largest).
    float z0 = viewPositionFromDepth(centreUv, uintBitsToFloat(sDepthMin)).z;
    float z1 = viewPositionFromDepth(centreUv, uintBitsToFloat(sDepthMax)).z;
    float zNear = max(z0, z1), zFar = min(z0, z1);
#ifdef DEPTH_MASK
    // 32 equal slices from zNear (slice 0) to zFar; depthSlice is monotonic
    // in z, so a sphere holding a surface point spans that point's slice.
    float sliceScale = 32.0 / max(zNear - zFar, 1e-30);
    if (tileHasSurface) {
        uint slices = 0u;
        for (uint k = 0u; k < uint(PIXELS_PER_THREAD); ++k) {
            if (!pixelInTile(k, size)) continue;
            ivec2 px = tilePixel(k);
            float depth = texelFetch(uDepth, px, 0).r;
            float type = floor(texelFetch(uAlbedo, px, 0).a * 255.0 + 0.5);
            if (isFarDepth(depth) || type == PIXEL_BACKGROUND) continue;
            slices |= 1u << depthSlice(viewPositionAtPixel(px, depth).z, zNear, sliceScale);
        }
        if (slices != 0u) atomicOr(sDepthSlices, slices);
    }
    barrier();
#endif
    uint words = uint(uEnd - uFirst + 31) / 32u;
    if (tileHasSurface) {
        // With COARSE only the candidates of the coarse tile's mask
        // (tiled_coarse.comp), else every candidate; each invocation owns
        // whole words of the list's bits.
        ScreenVolume volume = screenVolume(pixelMin, pixelMax, zNear, zFar);
#ifdef COARSE
        uvec2 coarseTile = gl_WorkGroupID.xy / uint(COARSE);
        uint coarseTilesX = (gl_NumWorkGroups.x + uint(COARSE) - 1u) / uint(COARSE);
        uint coarseBase = (coarseTile.y * coarseTilesX + coarseTile.x) * uint(WORDS);
#endif
        for (uint w = tid; w < words; w += uint(TILE_THREADS)) {
#ifdef COARSE
            uint bits = coarseMask[coarseBase + w];
#else
            int inWord = min(32, uEnd - uFirst - int(w) * 32);
            uint bits = inWord == 32 ? 0xFFFFFFFFu : (1u << uint(inWord)) - 1u;
#endif
            uint kept = 0u;
            while (bits != 0u) {
                int b = findLSB(bits);
                bits &= bits - 1u;
                vec4 pr = candidatePositionRadius(uFirst + int(w) * 32 + b);
                bool keep = sphereMeetsVolume(volume, pr.xyz, pr.w);
#ifdef DEPTH_MASK
                float r = pr.w * 1.0001 + 1e-5;  // sphereMeetsVolume's slack
                uint first = depthSlice(pr.z + r, zNear, sliceScale), last = depthSlice(pr.z - r, zNear, sliceScale);
                uint spanned = (last == 31u ? 0xFFFFFFFFu : (2u << last) - 1u) & ~((1u << first) - 1u);
                keep = keep && (spanned & sDepthSlices) != 0u;
#endif
                if (keep) kept |= 1u << uint(b);
            }
            sMask[w] = kept;
        }
    }
    barrier();

    // The list in candidate order: thread 0 counts each word's bits into
    // offsets, then every thread writes its words' candidates.
    if (tid == 0u) {
        uint listed = 0u, shadedListed = 0u;
        for (uint w = 0u; w < words; ++w) {
            uint bits = sMask[w];
            sBefore[w] = listed;
            listed += uint(bitCount(bits));
            // The shaded candidates are those below uShaded.
            int below = clamp(uShaded - uFirst - int(w) * 32, 0, 32);
            shadedListed += uint(bitCount(below == 32 ? bits : bits & ((1u << below) - 1u)));
        }
        sListed = listed;
        sShadedListed = shadedListed;
    }
    barrier();
    for (uint w = tid; w < words; w += uint(TILE_THREADS)) {
        uint bits = sMask[w];
        uint entry = sBefore[w];
        while (bits != 0u) {
            sList[entry++] = uint(uFirst + int(w) * 32 + findLSB(bits));
            bits &= bits - 1u;
        }
    }
    barrier();
    uint tileLights = sListed;
    // Shaded candidates come first in candidate order.
    uint toShade = (uFlags & FLAG_SHADE) != 0 ? sShadedListed : 0u;

    for (uint k = 0u; k < uint(PIXELS_PER_THREAD); k += uint(WALK)) {
        bool inside[WALK], lit[WALK];
        Surface surf[WALK];
        vec3 V[WALK];
        vec3 sum[WALK];
        uint shaded[WALK];
        bool any = false;
        for (int j = 0; j < WALK; ++j) {
            inside[j] = k + uint(j) < uint(PIXELS_PER_THREAD) && pixelInTile(k + uint(j), size);
            surf[j] = readSurface(min(tilePixel(k + uint(j)), size - 1));  // (unused when outside)
            V[j] = normalize(-surf[j].position);
            lit[j] = inside[j] && isSurface(surf[j]);
            any = any || lit[j];
            sum[j] = vec3(0.0);
            shaded[j] = 0u;
        }
        if (toShade > 0u && any) {
#ifdef TILE_WALK_MARK
            for (uint c = 0u; c < toShade; c += 32u) {
                uint n = min(32u, toShade - c);
                // Bit b: listed light c + b reaches one of this
                // invocation's WALK pixels (with slack: the shading loop
                // tests again, exactly).
                uint reach = 0u;
                for (uint b = 0u; b < n; ++b) {
                    int i = int(sList[c + b]);
                    vec4 pr = candidatePositionRadius(i), cone = candidateCone(i);
                    bool r = false;
                    for (int j = 0; j < WALK; ++j) {
                        float d;
                        vec3 L;
                        r = r || (lit[j] && candidateReaches(pr, cone, surf[j].position, MARK_SLACK, d, L));
                    }
                    if (r) reach |= 1u << b;
                }
                // In list order, so each pixel's sum is the same whatever
                // the other pixels of the walk.
                while (reach != 0u) {
                    uint b = uint(findLSB(reach));
                    reach &= reach - 1u;
                    shadeListed(int(sList[c + b]), surf, lit, V, sum, shaded);
                }
            }
#else
            for (uint e = 0u; e < toShade; ++e) shadeListed(int(sList[e]), surf, lit, V, sum, shaded);
#endif
        }
        for (int j = 0; j < WALK; ++j)
            if (inside[j]) writePixel(tilePixel(k + uint(j)), surf[j], sum[j], shaded[j], tileLights);
    }
}
