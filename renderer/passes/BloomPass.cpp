#include "renderer/passes/BloomPass.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <glm/glm.hpp>

#include "renderer/Error.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/gl/FullscreenTriangle.h"

namespace dw {

BloomPass::BloomPass(KnobRegistry& knobs) {
    enabled_ = knobs.addBool("bloom.enabled", true, "bloom", "bloom around pixels brighter than the threshold");
    method_ = knobs.addEnum("bloom.method", {"mip_sum", "dual_filter"}, "mip_sum", "bloom",
                            "Ferko's average of mip levels (seed 000 5.4) or Jimenez 2014's dual-filter chain", true);
    mipSum_ = knobs.choiceIndex(method_, "mip_sum");
    threshold_ = knobs.addFloat("bloom.threshold", 2.0, 0.0, 1e5, "bloom",
                                "luminance subtracted before blurring, as a multiple of the log-average (seed 002: 1)",
                                "x avg", false, true);
    intensity_ = knobs.addFloat("bloom.intensity", 0.6, 0.0, 8.0, "bloom", "strength of the composited bloom");
    levels_ = knobs.addInt("bloom.levels", 5, 1, kMaxLevels, "bloom", "mip levels blurred and summed (wider bloom)", "",
                           true);
    composite_ = knobs.addEnum("bloom.composite", {"ldr_luminance_alpha", "hdr_add"}, "ldr_luminance_alpha", "bloom",
                               "on the tone-mapped image with alpha = its luminance (seed 002 step 10, seed 004), "
                               "or added to the HDR image before tone mapping");
}

std::vector<OutputDecl> BloomPass::outputs() const {
    ResourceDesc bright = texture2D(GL_RGBA16F, 1, 0);  // half size, mip chain
    bright.maxLevels = kMaxLevels + 1;
    std::vector<OutputDecl> out = {
        {"bloom.bright", OutputKind::HdrColor, "thresholded L-buffer at half resolution", bright},
        {"bloom.result", OutputKind::HdrColor, "the bloom the tone mapper adds (half resolution)", texture2D(GL_RGBA16F, 1)}};
    for (int i = 1; i <= kMaxLevels; ++i)
        out.push_back({"bloom.mip" + std::to_string(i), OutputKind::HdrColor,
                       "bloom level " + std::to_string(i) + " of the filtered downsample chain (1/2^i of bloom.bright)"});
    return out;
}

std::string BloomPass::skipReason(const KnobRegistry& knobs, const Scene&) const {
    if (!knobs.get(enabled_)) return "switched off (bloom.enabled = false)";
    return {};
}

void BloomPass::makeTarget(Target& t, int w, int h, int levels, const char* label) {
    gl::MemoryOwner owner("bloom mips");
    t.texture = gl::Texture::create2D(GL_RGBA16F, std::max(w, 1), std::max(h, 1), levels);
    t.texture.setFilter(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    t.fbo = gl::Framebuffer::forColor(t.texture, label);
}

void BloomPass::setup(gl::ShaderLibrary& shaders) {
    brightProgram_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "bloom/bright.frag"});
    mipsum_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "bloom/mipsum.frag"});
    down_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "bloom/down.frag"});
    up_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "bloom/up.frag"});
    scale_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "bloom/scale.frag"});
    params_.create();
}

void BloomPass::resize(int width, int height, OutputRegistry& outputs) {
    // The dual filter's chains are the pass's own; bloom.bright and
    // bloom.result are allocated by the pipeline. bloom.mipN are bound to
    // whichever chain the method used, each frame.
    (void)outputs;
    const int w = std::max(width / 2, 1), h = std::max(height / 2, 1);
    for (int l = 0; l <= kMaxLevels; ++l) {
        makeTarget(down_chain_[l], w >> l, h >> l, 1, "bloom down");
        makeTarget(up_chain_[l], w >> l, h >> l, 1, "bloom up");
    }
}

void BloomPass::drawInto(const gl::Framebuffer& fbo, int w, int h) {
    glViewport(0, 0, w, h);
    fbo.bind();
    triangle_.draw();
}

void BloomPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const gl::Texture& hdr = ctx.texture("lbuffer");
    const gl::Texture& brightTexture = ctx.texture("bloom.bright");
    const gl::Texture& resultTexture = ctx.texture("bloom.result");
    // Bilinear between texels and mips is part of the method (and the tone
    // mapper upsamples the half-size result).
    brightTexture.setFilter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    resultTexture.setFilter(GL_LINEAR, GL_LINEAR);
    const gl::Framebuffer& brightFbo = bright_.get(ctx, {"bloom.bright"}, {}, "bloom bright");
    const gl::Framebuffer& resultFbo = result_.get(ctx, {"bloom.result"}, {}, "bloom result");
    const int w = brightTexture.width(), h = brightTexture.height();
    // A level narrower than kMinLevelTexels is no longer a blur of the image
    // but a smear across it, clamped at the edges: its halo would lean
    // towards the image's centre (a 320x180 frame has a 5x2 fifth level).
    int usable = 0;
    while (usable < kMaxLevels && (std::min(w, h) >> (usable + 1)) >= kMinLevelTexels) ++usable;
    const int levels = std::min({k.get(levels_), brightTexture.levels() - 1, usable});
    const bool mipSum = k.get(method_) == mipSum_;
    // Each draw sets what its shader reads; the rest keeps its last value.
    gpu::BloomParams p{};
    p.nanGuard = k.get(nanGuard_) ? 1 : 0;
    p.levels = levels;
    auto uploadTexels = [&](const gl::Texture* source, const gl::Texture& target) {
        if (source) p.sourceTexel = glm::vec2(1.0f / source->width(), 1.0f / source->height());
        p.targetTexel = glm::vec2(1.0f / target.width(), 1.0f / target.height());
        params_.upload(p, binding::PASS_UBO);
    };
    // 1. Threshold into level 0 of the bright chain.
    p.threshold = k.get(threshold_);
    params_.upload(p, binding::PASS_UBO);
    hdr.bind(binding::BLOOM_HDR_TEXTURE);
    ctx.texture("luminance.stats").bind(binding::BLOOM_STATS_TEXTURE);
    brightProgram_->use();
    drawInto(brightFbo, w, h);

    // 2. Downsample chain (both methods): level 0 is the bright image itself,
    //    each level the 13-tap filtered half of the one before.
    down_->use();
    const gl::Texture* source = &brightTexture;
    for (int l = 1; l <= levels; ++l) {
        const gl::Texture& dst = down_chain_[l].texture;
        uploadTexels(source, dst);
        glTextureParameteri(source->id(), GL_TEXTURE_MAX_LEVEL, 0);
        source->bind(binding::BLOOM_SOURCE_TEXTURE);
        drawInto(down_chain_[l].fbo, dst.width(), dst.height());
        glTextureParameteri(source->id(), GL_TEXTURE_MAX_LEVEL, 1000);
        source = &dst;
    }
    for (int i = levels + 1; i <= kMaxLevels; ++i)
        down_chain_[i].fbo.clearColor(0, 0.0f, 0.0f, 0.0f, 1.0f);  // not drawn this frame: black, not stale
    for (int i = 1; i <= kMaxLevels; ++i) ctx.outputs.bind("bloom.mip" + std::to_string(i), &down_chain_[i].texture, 4, 0);
    if (mipSum) {
        // 3. The average of the levels, each upsampled with a cubic B-spline.
        uploadTexels(nullptr, resultTexture);
        glTextureParameteri(brightTexture.id(), GL_TEXTURE_MAX_LEVEL, 0);
        brightTexture.bind(binding::BLOOM_BRIGHT_TEXTURE);
        for (int i = 1; i <= kMaxLevels; ++i) down_chain_[i].texture.bind(binding::BLOOM_LEVELS_TEXTURE + static_cast<GLuint>(i - 1));
        mipsum_->use();
        drawInto(resultFbo, w, h);
        glTextureParameteri(brightTexture.id(), GL_TEXTURE_MAX_LEVEL, 1000);
    } else {
        // 3. Upsample: each level = tent(coarser) + its own downsampled image.
        up_->use();
        const gl::Texture* coarse = &down_chain_[levels].texture;
        for (int l = levels - 1; l >= 0; --l) {
            const gl::Texture& same = l == 0 ? brightTexture : down_chain_[l].texture;
            const gl::Texture& dst = up_chain_[l].texture;
            uploadTexels(coarse, dst);
            coarse->bind(binding::BLOOM_COARSE_TEXTURE);
            glTextureParameteri(same.id(), GL_TEXTURE_MAX_LEVEL, 0);
            same.bind(binding::BLOOM_SAME_TEXTURE);
            drawInto(up_chain_[l].fbo, dst.width(), dst.height());
            glTextureParameteri(same.id(), GL_TEXTURE_MAX_LEVEL, 1000);
            coarse = &dst;
        }
        // With no coarser level (a tiny image) the bright image is the bloom.
        (levels > 0 ? up_chain_[0].texture : brightTexture).bind(binding::BLOOM_SOURCE_TEXTURE);
        scale_->use();
        drawInto(resultFbo, w, h);
    }
    stats_ = std::string(mipSum ? "mip sum" : "dual filter") + ", " + std::to_string(levels) + " levels from " +
             std::to_string(w) + "x" + std::to_string(h);
}

}  // namespace dw
