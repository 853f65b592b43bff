#include "renderer/lighting/TiledStrategy.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <tuple>

#include "renderer/gl/ShaderLoopLimit.h"
#include "renderer/gl/Texture.h"

namespace dw {

namespace {
constexpr const char* kTileCounts = "lighting.tile_counts";
// MAX_CANDIDATES of shaders/lighting/tiled.comp and tiled_coarse.comp: the
// bits of their shared-memory lists.
constexpr int kMaxCandidatesPerDispatch = 4096;
// COARSE: tiles per edge of a coarse tile (tiled_coarse.comp). 4 x 4 tiles of
// 16 pixels: at 10 000 lights, 640x360, the coarse pass costs about 2 ms and
// cuts the tiles' culling from about 25 ms to a few (docs/bench.md).
constexpr int kCoarseTiles = 4;
// WALK of tiled.comp (given it as a define): pixels per walk of the list,
// 4 measured best on llvmpipe (docs/bench.md), fewer when an invocation has fewer.
int walkOf(int pixelsPerThread) { return std::min(pixelsPerThread, 4); }

// The candidates one dispatch may take when the driver ends an invocation's
// loops after `limit` iterations in all (gl::shaderLoopIterationLimit; 0:
// no limit). llvmpipe counts, per batch of SIMD lanes, each loop's
// iterations (its slowest lane's) plus one for the test that ends it; the
// loops of a known small trip count (over the WALK pixels, the four planes)
// are unrolled and cost nothing. tiled.comp's invocation, with P pixels,
// one of T in its group, W = MAX_CANDIDATES / 32 words of candidate bits
// and N = 32 C candidates this dispatch, runs at most:
//   clearing the bits       ceil(W / T) + 1
//   depth bounds, slices    2 (P + 1)
//   culling                 ceil(W / T) (32 + 1) + 1   (a word's bits, then the words)
//   the list                W + 1, and ceil(W / T) (32 + 1) + 1
//   the walk                ceil(P / WALK) + 1 walks, each
//     marking:    C + 1 chunks of 32 + 1 marking and 32 + 1 shading iterations: 67 C + 1
//     branching:  N + 1 listed lights
// C is the largest whole number keeping the sum within 90% of the limit (a
// tenth in reserve), at least 1: on llvmpipe, 16 px tiles of 8 invocations
// take 3424 candidates a dispatch (lights start to drop at about 3830).
// Measured before this bound existed: with 4096 a dispatch, every light
// reaching every pixel of a tile, tiled shaded 3832 of 3900 lights there.
int candidatesPerDispatch(int pixelsPerThread, int threads, bool mark, int limit) {
    if (limit <= 0) return kMaxCandidatesPerDispatch;
    constexpr long words = kMaxCandidatesPerDispatch / 32;
    const long perThread = (words + threads - 1) / threads;
    const long before = (perThread + 1) + 2L * (pixelsPerThread + 1) + (perThread * 33 + 1) + (words + 1) +
                        (perThread * 33 + 1);
    const long walks = (pixelsPerThread + walkOf(pixelsPerThread) - 1) / walkOf(pixelsPerThread);
    const long budget = static_cast<long>(0.9 * limit) - before - (walks + 1);
    // Per walk: a fixed 1, and per chunk of 32 candidates 67 (marking) or 32 (branching).
    const long perWalkFixed = 1, perChunk = mark ? 67 : 32;
    const long chunks = budget > walks * perWalkFixed ? (budget - walks * perWalkFixed) / (walks * perChunk) : 0;
    return static_cast<int>(std::clamp<long>(chunks * 32, 32, kMaxCandidatesPerDispatch));
}
}

TiledStrategy::TiledStrategy(KnobRegistry& knobs) : tileSize_(declareTileSizeKnob(knobs)) {
    tileThreads_ = knobs.addInt("lighting.tile_threads", 0, 0, 1024, "lighting",
                                "invocations per tile work group of the tiled strategy, each shading every n-th pixel "
                                "of the tile (at most one per pixel); 0: auto, one per pixel on a GPU and one SIMD "
                                "batch on llvmpipe, whose barriers switch coroutines per batch",
                                "", true);
    depthMask_ = knobs.addBool("lighting.tile_depth_mask", true, "lighting",
                               "tiled: a light must also span one of 32 depth slices of the tile that holds a surface "
                               "(2.5D culling, Harada 2012), not only the tile's frustum between its nearest and "
                               "farthest surface");
    ambient_ = knobs.addBool("lighting.tile_ambient", true, "lighting",
                             "tiled: the compute pass also writes the ambient term, emission and the sky (with its "
                             "lights, in one image store per pixel), instead of a full-screen ambient pass before it "
                             "whose output the compute pass reads back; the image is the same either way (up to the "
                             "order of the sums)");
    walk_ = knobs.addEnum("lighting.tile_walk", {"auto", "mark", "branch"}, "auto", "lighting",
                          "tiled: how a pixel walks its tile's light list. mark: 32 listed lights at a time, first "
                          "mark which reach the invocation's pixels, then shade only those (on a CPU rasteriser a "
                          "branch every lane fails still runs its body, a loop ends with its last lane); branch: "
                          "test and shade each listed light in turn (a GPU's lanes skip a branch together); auto: "
                          "mark on llvmpipe, branch elsewhere. The image is the same either way");
    walkMark_ = knobs.choiceIndex(walk_, "mark");
    walkBranch_ = knobs.choiceIndex(walk_, "branch");
    coarse_ = knobs.addBool("lighting.tile_coarse", true, "lighting",
                            "tiled: a coarse pass first culls the lights against tiles of 4 x 4 tiles, and each tile "
                            "tests only its coarse tile's lights, not all of them (a two-level light grid); the "
                            "lists and the image are the same either way");
}

std::vector<OutputDecl> TiledStrategy::outputs() const {
    return {{kTileCounts, OutputKind::Count,
             "tiled: the bounded lights whose sphere meets each pixel's tile (its frustum between the tile's "
             "nearest and farthest surface), lights with a shadow map included (R32F)",
             texture2D(GL_R32F), 1, true}};
}

int TiledStrategy::simdLanes() {
    // llvmpipe names its vector width: "llvmpipe (LLVM 15.0.6, 256 bits)".
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (!renderer || !std::strstr(renderer, "llvmpipe")) return 0;
    int bits = 0;
    if (const char* comma = std::strstr(renderer, ", ")) bits = std::atoi(comma + 2);
    return bits >= 128 ? bits / 32 : 8;
}

void TiledStrategy::setup(gl::ShaderLibrary& shaders) {
    shaders_ = &shaders;
    cpuLanes_ = simdLanes();
    loopLimit_ = gl::shaderLoopIterationLimit();
    gl::MemoryOwner owner("light lists");
    candidates_.create();
    coarseMask_ = gl::Buffer::create(4, nullptr, true, "tiled coarse masks");
}

void TiledStrategy::dispatch(LightingFrame& f, const LightLists& lists, bool shade) {
    FrameContext& ctx = f.ctx;
    const bool counts = ctx.wants(kTileCounts);
    const bool overlap = shade && f.counting;
    // With lighting.tile_ambient a shading dispatch makes the L-buffer's
    // first write, with or without lights.
    if (!counts && (!shade || (lists.shaded == 0 && !writesFirstRadiance(ctx)))) return;

    const int tile = tileSizeOf(ctx.knobs, tileSize_);
    const int pixels = tile * tile;
    const int setThreads = ctx.knobs.get(tileThreads_);
    const int threads = std::min(setThreads > 0 ? setThreads : cpuLanes_ > 0 ? cpuLanes_ : pixels, pixels);
    const bool depthMask = ctx.knobs.get(depthMask_);
    const bool useCoarse = ctx.knobs.get(coarse_);
    const int walk = ctx.knobs.get(walk_);
    const bool mark = walk == walkMark_ || (walk != walkBranch_ && cpuLanes_ > 0);
    Programs& programs = programs_[{tile, threads, depthMask, useCoarse, mark}];
    if (!programs.fine) {
        std::vector<std::string> defines{"TILE_SIZE=" + std::to_string(tile), "TILE_THREADS=" + std::to_string(threads),
                                         "MAX_CANDIDATES=" + std::to_string(kMaxCandidatesPerDispatch),
                                         "WALK=" + std::to_string(walkOf((pixels + threads - 1) / threads))};
        if (useCoarse) {
            defines.push_back("COARSE=" + std::to_string(kCoarseTiles));
            programs.coarse = shaders_->get({.compute = "lighting/tiled_coarse.comp", .defines = defines});
        }
        if (depthMask) defines.push_back("DEPTH_MASK");
        if (mark) defines.push_back("TILE_WALK_MARK");
        programs.fine = shaders_->get({.compute = "lighting/tiled.comp", .defines = defines});
    }
    const gl::Program& program = *programs.fine;

    const GLuint tilesX = static_cast<GLuint>((ctx.width + tile - 1) / tile);
    const GLuint tilesY = static_cast<GLuint>((ctx.height + tile - 1) / tile);
    const GLuint coarseX = (tilesX + kCoarseTiles - 1) / kCoarseTiles;
    const GLuint coarseY = (tilesY + kCoarseTiles - 1) / kCoarseTiles;
    if (useCoarse) {
        gl::MemoryOwner owner("light lists");
        coarseMask_.ensureSize(
            std::size_t{coarseX} * coarseY * (kMaxCandidatesPerDispatch / 32) * sizeof(std::uint32_t),
            "tiled coarse masks");
        coarseMask_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::TILE_COARSE_MASK_SSBO);
    }

    lists.upload(candidates_, f.table);
    const gl::Texture& lbuffer = ctx.texture("lbuffer");
    glBindImageTexture(binding::TILED_LBUFFER_IMAGE, lbuffer.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    if (overlap) glBindImageTexture(binding::TILED_OVERLAP_IMAGE, ctx.texture("lighting.overlap").id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);
    if (counts) glBindImageTexture(binding::TILED_COUNTS_IMAGE, ctx.texture(kTileCounts).id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);
    // What came before through the framebuffer (the ambient pass and the
    // directional lights, without lighting.tile_ambient) is visible to the
    // first dispatch by GL's ordering; the barriers make
    // each coarse pass's masks visible to its tiles, each dispatch's image
    // stores visible to the next, and the last one's to the blending,
    // sampling and read-back after.
    const int total = static_cast<int>(lists.rows.size());
    const int perDispatch = candidatesPerDispatch((pixels + threads - 1) / threads, threads, mark, loopLimit_);
    for (int first = 0; first == 0 || first < total; first += perDispatch) {
        const int end = std::min(total, first + perDispatch);
        if (useCoarse) {
            const gl::Program& coarse = *programs.coarse;
            coarse.use();
            coarse.set(1, first);
            coarse.set(2, end);
            glDispatchCompute(coarseX, coarseY, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        }
        program.use();
        program.set(1, first);
        program.set(2, end);
        program.set(3, lists.shaded);
        program.set(4, (shade ? 1 : 0) | (overlap ? 2 : 0) | (counts ? 4 : 0) | (first > 0 ? 8 : 0) |
                           (shade && first == 0 && writesFirstRadiance(ctx) ? 16 : 0));
        glDispatchCompute(tilesX, tilesY, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
    }
}

StrategyCounts TiledStrategy::shade(LightingFrame& f) {
    const LightLists lists = LightLists::split(f);
    StrategyCounts c;
    c.culled = lists.culled;
    dispatch(f, lists, true);
    c.grid = lists.shaded;
    c.volumes = lists.shadeOneByOne(f);
    return c;
}

void TiledStrategy::writeOutputs(LightingFrame& f) {
    if (f.ctx.wants(kTileCounts)) dispatch(f, LightLists::split(f), false);
}

}  // namespace dw
