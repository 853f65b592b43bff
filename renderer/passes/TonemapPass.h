#pragma once
// Tone mapping (seed 000 sections 4.2 and 5.3; seed 002 steps 9 and 10):
// reads lbuffer, luminance.stats when an operator needs it, and bloom.result
// when bloom ran; writes tonemap.result (RGBA8, sRGB-encoded).
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"

namespace dw {

class TonemapPass : public RenderPass {
public:
    enum Operator { Simple = 0, Reinhard = 1, Aces = 2, Neutral = 3, Clamp = 4 };
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
    FloatKnob key_, white_, exposure_, bloomIntensity_;
    BoolKnob autoWhite_, srgb_, nanGuard_, autoExposure_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::Buffer params_;
    TargetFramebuffer target_;
};

}  // namespace dw
