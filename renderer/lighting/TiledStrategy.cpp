#include "renderer/lighting/TiledStrategy.h"

#include <algorithm>

#include "renderer/gl/Texture.h"

namespace dw {

namespace {
constexpr const char* kTileCounts = "lighting.tile_counts";
// MAX_CANDIDATES in shaders/lighting/tiled.comp: the bits of its shared-memory list.
constexpr int kMaxCandidatesPerDispatch = 4096;
}

TiledStrategy::TiledStrategy(KnobRegistry& knobs) : tileSize_(declareTileSizeKnob(knobs)) {}

std::vector<OutputDecl> TiledStrategy::outputs() const {
    return {{kTileCounts, OutputKind::Count,
             "tiled: the bounded lights whose sphere meets each pixel's tile (its frustum between the tile's "
             "nearest and farthest surface), lights with a shadow map included (R32F)",
             texture2D(GL_R32F), 1, true}};
}

void TiledStrategy::setup(gl::ShaderLibrary& shaders) {
    shaders_ = &shaders;
    candidates_ = gl::Buffer::create(sizeof(std::uint32_t), nullptr, true, "lighting candidates");
}

void TiledStrategy::dispatch(LightingFrame& f, const LightLists& lists, bool shade) {
    FrameContext& ctx = f.ctx;
    const bool counts = ctx.wants(kTileCounts);
    const bool overlap = shade && f.counting;
    if (!counts && (!shade || lists.shaded == 0)) return;

    const int tile = tileSizeOf(ctx.knobs, tileSize_);
    gl::ShaderLibrary::Handle& handle = programs_[tile];
    if (!handle) handle = shaders_->get({.compute = "lighting/tiled.comp", .defines = {"TILE_SIZE=" + std::to_string(tile)}});
    const gl::Program& program = *handle;

    lists.upload(candidates_);
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
