#pragma once
// The shared filter of every AO method (seed 000 section 4.6.3 eq. 4.7, seed
// 002 section 5.2): separable cross-bilateral blur (gaussian x 1/(delta +
// |depth difference|)) or plain gaussian for comparison (ssao_blur.*; skipped
// when the method says it denoised ao.raw itself, AoMethod::sharedBlur), then
// depth-aware upsampling to full resolution when the AO ran smaller. Reads
// ao.raw and gbuffer.depth; writes ao.filtered (full resolution), which the
// lighting pass multiplies into the ambient term.
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/ssao_blur.h"

namespace dw {

class AoFilterPass : public RenderPass {
public:
    explicit AoFilterPass(KnobRegistry& knobs);
    const char* name() const override { return "ao_filter"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"ao.filtered", OutputKind::Scalar, "filtered ambient accessibility at full resolution, 1 = open (R16F)",
                 texture2D(GL_R16F), 1}};
    }
    void connect(const KnobRegistry& knobs) override { aoEnabled_ = knobs.requireBool("ao.enabled"); }
    PassIO inputs(const KnobRegistry&) const override { return {{"ao.raw", "gbuffer.depth"}, {}}; }

    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

private:
    BoolKnob aoEnabled_;
    EnumKnob mode_;
    int off_ = 0;                       // ssao_blur.mode = off
    std::vector<std::string> defines_;  // SSAO_BLUR_MODE_*
    IntKnob width_;
    FloatKnob delta_;
    gl::ShaderLibrary::Handle blur_, upsample_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::SsaoBlurParams> params_;
    gl::Texture temp_[2];
    gl::Framebuffer tempFbo_[2];
    TargetFramebuffer full_;
    std::string stats_;
};

}  // namespace dw
