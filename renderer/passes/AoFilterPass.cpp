#include "renderer/passes/AoFilterPass.h"

#include <algorithm>
#include <glm/glm.hpp>

#include "renderer/ao/AoMethod.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Scene.h"

namespace dw {

AoFilterPass::AoFilterPass(KnobRegistry& knobs) {
    mode_ = knobs.addEnum("ssao_blur.mode", {"bilateral", "gaussian", "off"}, "bilateral", "ssao_blur",
                          "cross-bilateral (keeps occlusion from leaking across depth edges), plain gaussian, or none");
    off_ = knobs.choiceIndex(mode_, "off");
    defines_ = knobs.choiceDefines(mode_);
    width_ = knobs.addInt("ssao_blur.width", 15, 1, 61, "ssao_blur",
                          "kernel width in AO pixels (seed 002 uses up to 61); taps = 2 x (width / 2) + 1", "px", true);
    delta_ = knobs.addFloat("ssao_blur.delta", 0.05, 1e-4, 10.0, "ssao_blur",
                            "delta in the weight 1 / (delta + |d_center - d_current|) (eq. 4.7), in scene units of depth",
                            "units", false, true);
}

std::string AoFilterPass::skipReason(const KnobRegistry& knobs, const Scene& scene) const {
    if (!knobs.get(aoEnabled_)) return "switched off (ao.enabled = false)";
    if (scene.ambient == glm::vec3(0.0f)) return "the scene has no ambient light (AO only scales the ambient term)";
    return {};
}

void AoFilterPass::setup(gl::ShaderLibrary& shaders) {
    blur_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "ssao/blur.frag", .defines = defines_});
    upsample_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "ssao/upsample.frag", .defines = defines_});
    params_.create();
}

void AoFilterPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const gl::Texture& raw = ctx.texture("ao.raw");
    const gl::Texture& depth = ctx.texture("gbuffer.depth");
    const int w = raw.width(), h = raw.height();
    // The method that wrote ao.raw may have denoised it itself (none: the filter run alone).
    // Either way the upsampling stays depth-aware when ssao_blur.mode is bilateral.
    const bool blur = !ctx.aoMethod || ctx.aoMethod->sharedBlur(k);
    const int mode = k.get(mode_);
    const int radius = k.get(width_) / 2;
    gpu::SsaoBlurParams p{};
    p.mode = mode;
    p.aoSize = {w, h};
    p.delta = k.get(delta_);
    const gl::Texture* source = &raw;
    if (blur && mode != off_ && radius > 0) {
        for (int i = 0; i < 2; ++i)
            if (!temp_[i] || temp_[i].width() != w || temp_[i].height() != h) {
                temp_[i] = gl::Texture::create2D(GL_R16F, w, h);
                temp_[i].setFilter(GL_NEAREST, GL_NEAREST);
                tempFbo_[i] = gl::Framebuffer::forColor(temp_[i], "AO blur");
            }
        glViewport(0, 0, w, h);
        depth.bind(binding::AO_FILTER_DEPTH_TEXTURE);
        blur_->use();
        p.radius = radius;
        p.sigma = std::max(radius / 2.0f, 0.5f);
        for (int pass = 0; pass < 2; ++pass) {
            p.direction = pass == 0 ? glm::ivec2(1, 0) : glm::ivec2(0, 1);
            params_.upload(p, binding::PASS_UBO);
            source->bind(binding::AO_FILTER_SOURCE_TEXTURE);
            tempFbo_[pass].bind();
            triangle_.draw();
            source = &temp_[pass];
        }
    }
    // To full resolution; depth-aware when the AO ran smaller and blurring is bilateral.
    params_.upload(p, binding::PASS_UBO);
    source->bind(binding::AO_FILTER_SOURCE_TEXTURE);
    depth.bind(binding::AO_FILTER_DEPTH_TEXTURE);
    glViewport(0, 0, ctx.width, ctx.height);
    full_.get(ctx, {"ao.filtered"}, {}, "AO filtered").bind();
    upsample_->use();
    triangle_.draw();
    const std::string upsampled = w != ctx.width ? ", upsampled from " + std::to_string(w) + "x" + std::to_string(h) : "";
    if (!blur) stats_ = "no shared blur (the method denoised, or asked for none)" + upsampled;
    else if (mode == off_ || radius == 0) stats_ = "no blur" + upsampled;
    else stats_ = k.choice(mode_) + " blur, " + std::to_string(2 * radius + 1) + " taps" + upsampled;
}

}  // namespace dw
