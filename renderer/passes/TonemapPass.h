#pragma once
// Tone mapping (seed 000 sections 4.2 and 5.3; seed 002 steps 9 and 10):
// reads lbuffer, luminance.stats when an operator needs it, and bloom.result
// when bloom ran; writes tonemap.result (RGBA8, sRGB-encoded).
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/tonemap.h"

namespace dw {

class TonemapPass : public RenderPass {
public:
    explicit TonemapPass(KnobRegistry& knobs);
    const char* name() const override { return "tonemap"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"tonemap.result", OutputKind::Color, "tone-mapped image (RGBA8, sRGB-encoded)", texture2D(GL_RGBA8)}};
    }
    void connect(const KnobRegistry& knobs) override;
    PassIO inputs(const KnobRegistry& knobs) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;

private:
    EnumKnob operator_, bloomComposite_;
    int reinhard_ = 0;                  // tonemap.operator = reinhard (needs luminance.stats)
    std::vector<std::string> defines_;  // TONEMAP_OPERATOR_*, BLOOM_COMPOSITE_*
    FloatKnob key_, white_, exposure_, bloomIntensity_;
    BoolKnob autoWhite_, srgb_, nanGuard_, autoExposure_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::TonemapParams> params_;
    TargetFramebuffer target_;
};

}  // namespace dw
