#pragma once
// FXAA (seed 000 section 3.3; Lottes 2009) on the display image, aa.method=fxaa
// (the default): reads the post chain's current image (after depth of field
// when that is on); writes fxaa.result (RGBA8). docs/antialiasing.md.
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/Sampler.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/fxaa.h"

namespace dw {

class FxaaPass : public RenderPass {
public:
    explicit FxaaPass(KnobRegistry& knobs);
    const char* name() const override { return "fxaa"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"fxaa.result", OutputKind::Color, "the anti-aliased image (RGBA8)", texture2D(GL_RGBA8)}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {{kCurrentImage}, {}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;

private:
    EnumKnob method_;
    EnumKnob quality_;
    FloatKnob threshold_, thresholdMin_, subpixel_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer target_;
    gl::Sampler linear_;
    gl::ParamBuffer<gpu::FxaaParams> params_;
};

}  // namespace dw
