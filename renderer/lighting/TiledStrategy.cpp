#include "renderer/lighting/TiledStrategy.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <tuple>

#include "renderer/gl/Texture.h"

namespace dw {

namespace {
constexpr const char* kTileCounts = "lighting.tile_counts";
// MAX_CANDIDATES in shaders/lighting/tiled.comp: the bits of its shared-memory list.
constexpr int kMaxCandidatesPerDispatch = 4096;
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
    candidates_.create();
}

void TiledStrategy::dispatch(LightingFrame& f, const LightLists& lists, bool shade) {
    FrameContext& ctx = f.ctx;
    const bool counts = ctx.wants(kTileCounts);
    const bool overlap = shade && f.counting;
    if (!counts && (!shade || lists.shaded == 0)) return;

    const int tile = tileSizeOf(ctx.knobs, tileSize_);
    const int pixels = tile * tile;
    const int setThreads = ctx.knobs.get(tileThreads_);
    const int threads = std::min(setThreads > 0 ? setThreads : cpuLanes_ > 0 ? cpuLanes_ : pixels, pixels);
    const bool depthMask = ctx.knobs.get(depthMask_);
    gl::ShaderLibrary::Handle& handle = programs_[{tile, threads, depthMask}];
    if (!handle) {
        std::vector<std::string> defines{"TILE_SIZE=" + std::to_string(tile), "TILE_THREADS=" + std::to_string(threads)};
        if (depthMask) defines.push_back("DEPTH_MASK");
        handle = shaders_->get({.compute = "lighting/tiled.comp", .defines = defines});
    }
    const gl::Program& program = *handle;

    lists.upload(candidates_, f.table);
    const gl::Texture& lbuffer = ctx.texture("lbuffer");
    glBindImageTexture(0, lbuffer.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    if (overlap) glBindImageTexture(1, ctx.texture("lighting.overlap").id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);
    if (counts) glBindImageTexture(2, ctx.texture(kTileCounts).id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);
    program.use();
    program.set(3, lists.shaded);
    // What came before through the framebuffer (ambient, directional lights)
    // is visible to the first dispatch by GL's ordering; the barriers make
    // each dispatch's image stores visible to the next, and the last one's to
    // the blending, sampling and read-back after.
    const int total = static_cast<int>(lists.rows.size());
    for (int first = 0; first == 0 || first < total; first += kMaxCandidatesPerDispatch) {
        program.set(1, first);
        program.set(2, std::min(total, first + kMaxCandidatesPerDispatch));
        program.set(4, (shade ? 1 : 0) | (overlap ? 2 : 0) | (counts ? 4 : 0) | (first > 0 ? 8 : 0));
        glDispatchCompute(static_cast<GLuint>((ctx.width + tile - 1) / tile), static_cast<GLuint>((ctx.height + tile - 1) / tile), 1);
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                        GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
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
