#include "renderer/passes/SsaaPass.h"

#include "renderer/gl/Texture.h"
#include "renderer/passes/AaMethod.h"

namespace dw {

namespace {
int log2Of(int factor) { return factor >= 4 ? 2 : factor >= 2 ? 1 : 0; }
}  // namespace

int SsaaPass::cappedFactor(int requested, int width, int height) {
    int f = requested;
    while (f > 1 && (static_cast<long long>(width) * f * static_cast<long long>(height) * f > kMaxPixels ||
                     width * f > kMaxSide || height * f > kMaxSide))
        f /= 2;
    return f;
}

SsaaPass::SsaaPass(KnobRegistry& knobs) {
    method_ = declareAaMethod(knobs, "ssaa",
                              "supersampling: the whole frame rendered at aa.ssaa_factor times the size per axis and "
                              "box-filtered down");
    factorKnob_ = knobs.addEnum("aa.ssaa_factor", {"2", "4"}, "2", kAaGroup,
                                "SSAA's rendered pixels per output pixel along each axis (2: 2x2, 4: 4x4 samples); "
                                "the supersampled frame is held to 3840x2160 pixels (a larger one halves it, said)",
                                true);
}

std::vector<OutputDecl> SsaaPass::outputs() const {
    return {
        {"ssaa.result", OutputKind::Color, "the supersampled display image box-filtered to the output size (RGBA8)",
         texture2D(GL_RGBA8)},
        {"ssaa.lbuffer", OutputKind::HdrColor,
         "the supersampled L-buffer box-filtered to the output size: each pixel's area mean of radiance (RGBA32F)",
         texture2D(GL_RGBA32F), 4, true},
    };
}

ResourceDesc SsaaPass::resource(const OutputDecl& output, const KnobRegistry&) const {
    ResourceDesc d = output.resource;
    d.shift = log2Of(factor_);  // the frame is factor_ times the output size
    return d;
}

std::string SsaaPass::skipReason(const KnobRegistry& knobs, const Scene&) const {
    return aaMethodSkipReason(knobs, method_, "ssaa");
}

FrameSampling SsaaPass::sampling(const KnobRegistry& knobs, std::uint64_t, int width, int height) {
    factor_ = 1;
    stats_.clear();
    warning_.clear();
    if (!aaMethodSkipReason(knobs, method_, "ssaa").empty()) return {};
    const int requested = std::stoi(knobs.choice(factorKnob_));
    factor_ = cappedFactor(requested, width, height);
    stats_ = std::to_string(factor_) + "x" + std::to_string(factor_) + " samples a pixel, rendered at " +
             std::to_string(width * factor_) + "x" + std::to_string(height * factor_);
    if (factor_ != requested)
        warning_ = "aa.ssaa_factor " + std::to_string(requested) + " is capped to " + std::to_string(factor_) + " at " +
                   std::to_string(width) + "x" + std::to_string(height) +
                   ": the supersampled frame is held to 3840x2160 pixels and 16384 a side";
    return {factor_, glm::vec2(0.0f)};
}

void SsaaPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "post/ssaa_resolve.frag"});
    params_.create();
}

void SsaaPass::resolve(FrameContext& ctx, const gl::Texture& source, const std::string& target, bool srgb) {
    gpu::SsaaParams p{};
    p.factor = factor_;
    p.srgbInput = srgb ? 1 : 0;
    params_.upload(p, binding::PASS_UBO);
    source.bind(binding::SSAA_SOURCE_TEXTURE);
    program_->use();
    (target == "ssaa.result" ? result_ : lbuffer_).get(ctx, {target}, {}, "SSAA resolve").bind();
    glViewport(0, 0, ctx.width / factor_, ctx.height / factor_);
    triangle_.draw();
}

void SsaaPass::execute(FrameContext& ctx) {
    resolve(ctx, ctx.currentImage(), "ssaa.result", ctx.knobs.get(srgb_));
    if (ctx.wants("ssaa.lbuffer")) resolve(ctx, ctx.texture("lbuffer"), "ssaa.lbuffer", false);
}

}  // namespace dw
