#include "renderer/passes/FxaaPass.h"

#include <glm/glm.hpp>

namespace dw {

FxaaPass::FxaaPass(KnobRegistry& knobs) {
    enabled_ = knobs.addBool("fxaa.enabled", true, "fxaa", "fast approximate anti-aliasing of the final image");
    quality_ = knobs.addEnum("fxaa.quality", {"low", "medium", "high"}, 1, "fxaa",
                             "how far the search along an edge goes (4, 8 or 12 steps)", true);
    threshold_ = knobs.addFloat("fxaa.edge_threshold", 0.125, 0.03, 0.5, "fxaa",
                                "local contrast, relative to the brightest neighbour, that marks an edge", "", true);
    thresholdMin_ = knobs.addFloat("fxaa.edge_threshold_min", 0.0312, 0.0, 0.2, "fxaa",
                                   "absolute contrast below which dark areas are left alone");
    subpixel_ = knobs.addFloat("fxaa.subpixel", 0.75, 0.0, 1.0, "fxaa", "how much single-pixel features are softened");
}

std::string FxaaPass::skipReason(const KnobRegistry& knobs, const Scene&) const {
    if (!knobs.get(enabled_)) return "switched off (fxaa.enabled = false)";
    return {};
}

void FxaaPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "post/fxaa.frag"});
    linear_ = gl::Sampler::create(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, "fxaa linear");
}

void FxaaPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const gl::Texture& input = ctx.currentImage();
    // Bilinear reads between pixels are part of the method; the sampler keeps
    // the shared image itself nearest for everyone else.
    input.bind(0);
    linear_.bind(0);
    program_->use();
    program_->set(0, glm::vec4(k.get(threshold_), k.get(thresholdMin_), k.get(subpixel_), 0.0f));
    static const int steps[] = {4, 8, 12};
    program_->set(1, steps[k.get(quality_)]);
    target_.get(ctx, {"fxaa.result"}, {}, "FXAA").bind();
    triangle_.draw();
}

}  // namespace dw
