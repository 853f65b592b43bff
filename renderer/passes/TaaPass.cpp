#include "renderer/passes/TaaPass.h"
#include "renderer/gl/MemoryLedger.h"

#include <cstdio>

#include "renderer/passes/AaMethod.h"

namespace dw {

namespace {

double radicalInverse(unsigned index, unsigned base) {
    double result = 0.0, scale = 1.0 / base;
    for (; index > 0; index /= base, scale /= base) result += scale * (index % base);
    return result;
}

// The translation in NDC the pipeline applies after the projection for a
// jitter of `jitter` pixels at `width` x `height` (Pipeline::cameraUniforms).
glm::dmat4 jitterShift(glm::vec2 jitter, double width, double height) {
    glm::dmat4 shift(1.0);
    shift[3][0] = 2.0 * jitter.x / width;
    shift[3][1] = 2.0 * jitter.y / height;
    return shift;
}

}  // namespace

glm::vec2 TaaPass::jitter(std::uint64_t frameIndex) {
    const unsigned i = static_cast<unsigned>(frameIndex % kJitterPeriod) + 1;
    return {static_cast<float>(radicalInverse(i, 2) - 0.5), static_cast<float>(radicalInverse(i, 3) - 0.5)};
}

TaaPass::TaaPass(KnobRegistry& knobs) {
    method_ = declareAaMethod(knobs, "taa",
                              "temporal anti-aliasing: a sub-pixel Halton(2,3) jitter each frame, the history "
                              "reprojected, clamped to the neighbourhood and blended (aa.taa_blend)");
    blend_ = knobs.addFloat("aa.taa_blend", 0.1, 0.02, 1.0, kAaGroup,
                            "TAA: the current frame's weight in the blend with the history (1: no history)", "", true);
    reject_ = knobs.addFloat("aa.taa_reject", 0.1, 0.0, 1.0, kAaGroup,
                             "TAA: a history the neighbourhood clamp moves by more than this (YCoCg distance of "
                             "display values 0-1) is thrown away (taa.rejected)");
}

std::vector<OutputDecl> TaaPass::outputs() const {
    return {
        {"taa.result", OutputKind::Color, "the temporally anti-aliased display image (RGBA8)", texture2D(GL_RGBA8)},
        {"taa.rejected", OutputKind::Scalar,
         "1 where TAA threw the history away (off screen, clamped beyond aa.taa_reject, or none yet), else 0 (R8)",
         texture2D(GL_R8), 1},
    };
}

std::string TaaPass::skipReason(const KnobRegistry& knobs, const Scene&) const {
    return aaMethodSkipReason(knobs, method_, "taa");
}

FrameSampling TaaPass::sampling(const KnobRegistry& knobs, std::uint64_t frameIndex, int, int) {
    jitter_ = glm::vec2(0.0f);
    if (!aaMethodSkipReason(knobs, method_, "taa").empty()) return {};
    jitter_ = jitter(frameIndex);
    return {1, jitter_};
}

void TaaPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "post/taa.frag"});
    linear_ = gl::Sampler::create(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, "taa history");
    nearest_ = gl::Sampler::create(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, "taa nearest");
    params_.create();
}

bool TaaPass::historyUsable(const FrameContext& ctx) {
    const char* why = nullptr;
    if (!history_ || history_.width() != ctx.width || history_.height() != ctx.height) why = "no history at this size";
    else if (previousFrame_ + 1 != ctx.frameIndex) why = "no history from the frame before";
    else if (previousScene_ != &ctx.scene) why = "a new scene";
    char line[160];
    std::snprintf(line, sizeof line, "jitter (%+.3f, %+.3f) px, Halton(2,3) point %d of %d; %s", jitter_.x, jitter_.y,
                  static_cast<int>(ctx.frameIndex % kJitterPeriod) + 1, kJitterPeriod,
                  why ? why : "history reprojected");
    stats_ = line;
    return why == nullptr;
}

void TaaPass::keepHistory(const FrameContext& ctx, const glm::dmat4& unjitteredClip) {
    if (!history_ || history_.width() != ctx.width || history_.height() != ctx.height) {
        gl::MemoryOwner owner("taa history");
        history_ = gl::Texture::create2D(GL_RGBA8, ctx.width, ctx.height);
    }
    const gl::Texture& result = ctx.texture("taa.result");
    glCopyImageSubData(result.id(), GL_TEXTURE_2D, 0, 0, 0, 0, history_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.width,
                       ctx.height, 1);
    previousClip_ = unjitteredClip;
    previousFrame_ = ctx.frameIndex;
    previousScene_ = &ctx.scene;
}

void TaaPass::execute(FrameContext& ctx) {
    const bool valid = historyUsable(ctx);
    const glm::dmat4 unjitteredClip =
        glm::inverse(jitterShift(jitter_, ctx.width, ctx.height)) * ctx.camera.worldToClip();
    gpu::TaaParams p{};
    // This frame's NDC -> world (absolute, double) -> last frame's clip.
    p.reprojection = glm::mat4(previousClip_ * glm::inverse(unjitteredClip));
    p.blend = ctx.knobs.get(blend_);
    p.rejectDistance = ctx.knobs.get(reject_);
    p.historyValid = valid ? 1 : 0;
    params_.upload(p, binding::PASS_UBO);
    ctx.currentImage().bind(binding::TAA_CURRENT_TEXTURE);
    nearest_.bind(binding::TAA_CURRENT_TEXTURE);
    if (valid) {
        history_.bind(binding::TAA_HISTORY_TEXTURE);
        linear_.bind(binding::TAA_HISTORY_TEXTURE);
    }
    ctx.texture("gbuffer.depth").bind(binding::TAA_DEPTH_TEXTURE);
    nearest_.bind(binding::TAA_DEPTH_TEXTURE);
    program_->use();
    target_.get(ctx, {"taa.result", "taa.rejected"}, {}, "TAA").bind();
    triangle_.draw();
    keepHistory(ctx, unjitteredClip);
}

}  // namespace dw
