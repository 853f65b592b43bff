#include "renderer/passes/DofPass.h"

#include "renderer/Error.h"
#include "renderer/scene/GpuScene.h"

namespace dw {

DofPass::DofPass(KnobRegistry& knobs) {
    enabled_ = knobs.addBool("dof.enabled", false, "dof", "depth of field on the tone-mapped image");
    focus_ = knobs.addFloat("dof.focus_distance", 10.0, 0.01, 10000.0, "dof", "distance in focus, along the view axis",
                            "units", false, true);
    range_ = knobs.addFloat("dof.focus_range", 4.0, 0.0, 10000.0, "dof",
                            "depth band around the focus that stays sharp; the blur reaches its maximum one band further",
                            "units", false, true);
    radius_ = knobs.addFloat("dof.max_radius", 6.0, 0.0, 32.0, "dof", "largest blur radius", "px", true);
    samples_ = knobs.addInt("dof.samples", 24, 4, 128, "dof",
                           "gather samples per pixel (the near layer takes twice as many, in each of its two gathers)", "",
                           true);
    near_ = knobs.addBool("dof.near_blur", true, "dof", "blur what is nearer than the focus");
    far_ = knobs.addBool("dof.far_blur", true, "dof", "blur what is farther than the focus");
    // Declared by the tone mapper, which comes first: whether its output is
    // sRGB-encoded, so the blur averages linear values.
    const std::optional<int> srgb = knobs.find("tonemap.srgb");
    if (!srgb) throw Error("the depth-of-field pass needs the tone mapper's knob tonemap.srgb");
    srgb_ = BoolKnob{*srgb};
}

std::string DofPass::skipReason(const KnobRegistry& knobs, const Scene&) const {
    if (!knobs.get(enabled_)) return "switched off (dof.enabled = false)";
    return {};
}

void DofPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "post/dof.frag"});
    params_.create();
}

void DofPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    ctx.currentImage().bind(binding::DOF_IMAGE_TEXTURE);
    ctx.texture("gbuffer.depth").bind(binding::DOF_DEPTH_TEXTURE);
    program_->use();
    gpu::DofParams p{};
    p.nearBlur = k.get(near_) ? 1 : 0;
    p.farBlur = k.get(far_) ? 1 : 0;
    p.sampleCount = k.get(samples_);
    p.focusDistance = k.get(focus_);
    p.focusRange = k.get(range_);
    p.maxRadius = k.get(radius_);
    p.srgbInput = k.get(srgb_) ? 1 : 0;
    for (int write : {gpu::DOF_WRITE_RESULT, gpu::DOF_WRITE_COC, gpu::DOF_WRITE_NEAR_ALPHA}) {
        if (write == gpu::DOF_WRITE_COC && !ctx.wants("dof.coc")) continue;
        if (write == gpu::DOF_WRITE_NEAR_ALPHA && !ctx.wants("dof.near_alpha")) continue;
        p.outputKind = write;
        params_.upload(p, binding::PASS_UBO);
        if (write == gpu::DOF_WRITE_COC) coc_.get(ctx, {"dof.coc"}, {}, "circle of confusion").bind();
        else if (write == gpu::DOF_WRITE_NEAR_ALPHA) nearAlpha_.get(ctx, {"dof.near_alpha"}, {}, "near field alpha").bind();
        else result_.get(ctx, {"dof.result"}, {}, "depth of field").bind();
        triangle_.draw();
    }
}

}  // namespace dw
