#include "renderer/passes/LuminancePass.h"

#include <algorithm>
#include <optional>

#include <glm/glm.hpp>

#include "renderer/passes/AaMethod.h"

#include "renderer/scene/GpuScene.h"

namespace dw {

namespace {
// Work groups (first pass: tiles) needed for `count` items of which a group takes `perGroup`.
GLuint groups(std::size_t count, int perGroup) {
    const auto n = static_cast<std::size_t>(perGroup);
    return static_cast<GLuint>((count + n - 1) / n);
}

std::size_t tileCount(int width, int height) {
    return static_cast<std::size_t>(groups(static_cast<std::size_t>(width), gpu::LUMINANCE_TILE)) *
           groups(static_cast<std::size_t>(height), gpu::LUMINANCE_TILE);
}
}  // namespace

LuminancePass::LuminancePass(KnobRegistry& knobs) {
    delta_ = knobs.addFloat("luminance.log_delta", 1e-4, 1e-8, 1.0, "luminance",
                            "delta in the log-average exp(mean(log(delta + L))) (seed 000 eq. 4.2), keeping black "
                            "pixels from sending the average to zero",
                            "", false, true);
    background_ = knobs.addEnum("luminance.background", {"include", "exclude"}, "include", "luminance",
                                "whether background pixels (no geometry) count in the statistics; the seed counts "
                                "every pixel, which lets a black background darken the log-average");
    exclude_ = knobs.choiceIndex(background_, "exclude");
}

PassIO LuminancePass::inputs(const KnobRegistry& knobs) const {
    PassIO io{{"lbuffer"}, {}};
    if (knobs.get(background_) == exclude_) io.inputs.push_back("gbuffer.depth");
    return io;
}

void LuminancePass::setup(gl::ShaderLibrary& shaders) {
    first_ = shaders.get({.compute = "tonemap/luminance_reduce.comp", .defines = {"FIRST_PASS"}});
    next_ = shaders.get({.compute = "tonemap/luminance_reduce.comp"});
    finalize_ = shaders.get({.compute = "tonemap/luminance_reduce.comp", .defines = {"FINALIZE"}});
    stats_ = gl::Texture::create2D(GL_RGBA32F, 1, 1);
    stats_.setFilter(GL_NEAREST, GL_NEAREST);
    params_.create();
}

void LuminancePass::resize(int width, int height, OutputRegistry& outputs) {
    const size_t tiles = tileCount(width, height);
    ping_ = gl::Buffer::create(tiles * sizeof(glm::vec4), nullptr, false, "luminance partials A");
    pong_ = gl::Buffer::create(tiles * sizeof(glm::vec4), nullptr, false, "luminance partials B");
    outputs.bind("luminance.stats", &stats_, 4);
}

void LuminancePass::reduce(const gl::Texture& hdr, float delta, const gl::Texture* depthMask, int footprint) {
    footprint = std::max(footprint, 1);
    const int w = hdr.width() / footprint, h = hdr.height() / footprint;
    const size_t tiles = tileCount(w, h);
    if (ping_.size() < tiles * sizeof(glm::vec4)) {
        ping_ = gl::Buffer::create(tiles * sizeof(glm::vec4), nullptr, false, "luminance partials A");
        pong_ = gl::Buffer::create(tiles * sizeof(glm::vec4), nullptr, false, "luminance partials B");
    }
    hdr.bind(binding::LUMINANCE_HDR_TEXTURE);
    if (depthMask) depthMask->bind(binding::LUMINANCE_DEPTH_TEXTURE);
    gpu::LuminanceParams p{};
    p.delta = delta;
    p.skipBackground = depthMask ? 1 : 0;
    p.footprint = footprint;
    params_.upload(p, binding::PASS_UBO);
    first_->use();
    ping_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::LUMINANCE_REDUCE_OUT_SSBO);
    glDispatchCompute(groups(static_cast<std::size_t>(w), gpu::LUMINANCE_TILE),
                      groups(static_cast<std::size_t>(h), gpu::LUMINANCE_TILE), 1);
    size_t count = tiles;
    const gl::Buffer* in = &ping_;
    const gl::Buffer* out = &pong_;
    next_->use();
    while (count > 1) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        const GLuint n = groups(count, gpu::LUMINANCE_GROUP);
        in->bindBase(GL_SHADER_STORAGE_BUFFER, binding::LUMINANCE_REDUCE_IN_SSBO);
        out->bindBase(GL_SHADER_STORAGE_BUFFER, binding::LUMINANCE_REDUCE_OUT_SSBO);
        p.count = static_cast<int>(count);
        params_.upload(p, binding::PASS_UBO);
        glDispatchCompute(n, 1, 1);
        count = n;
        std::swap(in, out);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    in->bindBase(GL_SHADER_STORAGE_BUFFER, binding::LUMINANCE_REDUCE_IN_SSBO);
    finalize_->use();
    glBindImageTexture(binding::LUMINANCE_STATS_IMAGE, stats_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void LuminancePass::execute(FrameContext& ctx) {
    const gl::Texture* mask = ctx.knobs.get(background_) == exclude_ ? ctx.outputs.find("gbuffer.depth")->texture : nullptr;
    const gl::Texture& lbuffer = *ctx.outputs.find("lbuffer")->texture;
    reduce(lbuffer, ctx.knobs.get(delta_), mask, ssaaFootprint(ctx, lbuffer));
}

// SSAA's rendered pixels per output pixel along each axis this frame: the
// L-buffer's width over ssaa.result's (the output size) when aa.method is
// ssaa (its factor, after SsaaPass's cap); 1 otherwise.
int LuminancePass::ssaaFootprint(const FrameContext& ctx, const gl::Texture& lbuffer) {
    const std::optional<int> method = ctx.knobs.find(kAaMethodKnob);
    if (!method || ctx.knobs.format(*method) != "ssaa") return 1;
    const auto* result = ctx.outputs.find("ssaa.result");
    if (!result || !result->texture || result->texture->width() <= 0) return 1;
    return std::max(lbuffer.width() / result->texture->width(), 1);
}

}  // namespace dw
