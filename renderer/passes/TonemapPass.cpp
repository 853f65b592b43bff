#include "renderer/passes/TonemapPass.h"

#include "renderer/scene/GpuScene.h"

namespace dw {

TonemapPass::TonemapPass(KnobRegistry& knobs) {
    operator_ = knobs.addEnum("tonemap.operator", {"simple", "reinhard", "aces", "neutral", "clamp"}, "reinhard", "tonemap",
                              "simple L/(1+L) (seed 000 eq. 4.1); Reinhard's global operator with log-average "
                              "luminance and L_white (eqs. 4.3, 4.4); ACES (Hill's fit); Khronos PBR Neutral; clamp");
    reinhard_ = knobs.choiceIndex(operator_, "reinhard");
    key_ = knobs.addFloat("tonemap.key", 0.18, 0.01, 2.0, "tonemap",
                          "Reinhard key value a: the luminance the log-average maps to (eq. 4.3)");
    autoWhite_ = knobs.addBool("tonemap.auto_white", true, "tonemap",
                               "L_white = the image's highest luminance, from the GPU max-reduction (seed 000 5.3.1)");
    white_ = knobs.addFloat("tonemap.white", 4.0, 0.01, 1e4, "tonemap",
                            "manual L_white (scaled luminance mapped to white) when auto_white is off", "", false, true);
    exposure_ = knobs.addFloat("tonemap.exposure", 0.0, -10.0, 10.0, "tonemap",
                               "exposure applied to the L-buffer before the operator", "EV");
    srgb_ = knobs.addBool("tonemap.srgb", true, "tonemap", "encode the output with the sRGB transfer curve");
    autoExposure_ = knobs.addBool("tonemap.auto_exposure", false, "tonemap",
                                  "scale by key / log-average for the simple, ACES, neutral and clamp operators too "
                                  "(Reinhard always does)");
    nanGuard_ = knobs.addBool("tonemap.nan_guard", true, "tonemap",
                              "replace NaN with 0 and infinity with 65504 before tone mapping (and in the bloom input)");
}

void TonemapPass::connect(const KnobRegistry& knobs) {
    bloomIntensity_ = knobs.requireFloat("bloom.intensity");
    bloomComposite_ = knobs.requireEnum("bloom.composite");
    defines_ = knobs.choiceDefines(operator_);
    for (const std::string& d : knobs.choiceDefines(bloomComposite_)) defines_.push_back(d);
}

PassIO TonemapPass::inputs(const KnobRegistry& knobs) const {
    PassIO io;
    io.inputs = {"lbuffer"};
    if (knobs.get(operator_) == reinhard_ || knobs.get(autoExposure_)) io.inputs.push_back("luminance.stats");
    io.optionalInputs = {"bloom.result"};
    return io;
}

void TonemapPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "tonemap/tonemap.frag", .defines = defines_});
    params_.create();
}

void TonemapPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const bool bloom = ctx.produced("bloom.result");
    gpu::TonemapParams p{};
    p.toneOperator = k.get(operator_);
    p.autoWhite = k.get(autoWhite_) ? 1 : 0;
    p.srgbOutput = k.get(srgb_) ? 1 : 0;
    p.nanGuard = k.get(nanGuard_) ? 1 : 0;
    p.bloom = bloom ? 1 : 0;
    p.bloomComposite = k.get(bloomComposite_);
    p.autoExposure = k.get(autoExposure_) ? 1 : 0;
    p.key = k.get(key_);
    p.white = k.get(white_);
    p.exposure = k.get(exposure_);
    p.bloomIntensity = k.get(bloomIntensity_);
    params_.upload(p, binding::PASS_UBO);
    ctx.texture("lbuffer").bind(binding::TONEMAP_HDR_TEXTURE);
    if (ctx.produced("luminance.stats")) ctx.texture("luminance.stats").bind(binding::TONEMAP_STATS_TEXTURE);
    if (bloom) ctx.texture("bloom.result").bind(binding::TONEMAP_BLOOM_TEXTURE);
    target_.get(ctx, {"tonemap.result"}, {}, "tone-mapped image").bind();
    program_->use();
    triangle_.draw();
}

}  // namespace dw
