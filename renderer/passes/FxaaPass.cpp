#include "renderer/passes/FxaaPass.h"

#include <iterator>

#include "renderer/passes/AaMethod.h"
#include "renderer/scene/GpuScene.h"

namespace dw {

namespace {
// fxaa.quality's choices with the search steps each stands for, in one place.
struct Quality {
    const char* name;
    int steps;
};
constexpr Quality kQualities[] = {{"low", 4}, {"medium", 8}, {"high", 12}};
}  // namespace

FxaaPass::FxaaPass(KnobRegistry& knobs) {
    method_ = declareAaMethod(knobs, "fxaa",
                              "fast approximate anti-aliasing (Lottes 2009) of the display image, edges found by "
                              "contrast and blended along them",
                              true);
    std::vector<std::string> names;
    std::string steps;
    for (const Quality& q : kQualities) {
        steps += names.empty() ? "" : (names.size() + 1 == std::size(kQualities) ? " or " : ", ");
        steps += std::to_string(q.steps);
        names.emplace_back(q.name);
    }
    quality_ = knobs.addEnum("fxaa.quality", names, "medium", "fxaa",
                             "how far the search along an edge goes (" + steps + " steps)", true);
    threshold_ = knobs.addFloat("fxaa.edge_threshold", 0.125, 0.03, 0.5, "fxaa",
                                "local contrast, relative to the brightest neighbour, that marks an edge", "", true);
    thresholdMin_ = knobs.addFloat("fxaa.edge_threshold_min", 0.0312, 0.0, 0.2, "fxaa",
                                   "absolute contrast below which dark areas are left alone");
    subpixel_ = knobs.addFloat("fxaa.subpixel", 0.75, 0.0, 1.0, "fxaa", "how much single-pixel features are softened");
}

std::string FxaaPass::skipReason(const KnobRegistry& knobs, const Scene&) const {
    return aaMethodSkipReason(knobs, method_, "fxaa");
}

void FxaaPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "post/fxaa.frag"});
    linear_ = gl::Sampler::create(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, "fxaa linear");
    params_.create();
}

void FxaaPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const gl::Texture& input = ctx.currentImage();
    // Bilinear reads between pixels are part of the method; the sampler keeps
    // the shared image itself nearest for everyone else.
    input.bind(binding::FXAA_IMAGE_TEXTURE);
    linear_.bind(binding::FXAA_IMAGE_TEXTURE);
    gpu::FxaaParams p{};
    p.edgeThreshold = k.get(threshold_);
    p.edgeThresholdMin = k.get(thresholdMin_);
    p.subpixel = k.get(subpixel_);
    p.searchSteps = kQualities[k.get(quality_)].steps;
    params_.upload(p, binding::PASS_UBO);
    program_->use();
    target_.get(ctx, {"fxaa.result"}, {}, "FXAA").bind();
    triangle_.draw();
}

}  // namespace dw
