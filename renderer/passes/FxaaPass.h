#pragma once
// FXAA (seed 000 section 3.3) on the tone-mapped image: reads dof.result when
// depth of field is on, else tonemap.result; writes fxaa.result (RGBA8).
#include "renderer/KnobRegistry.h"
#include "renderer/RenderPass.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/Sampler.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"

namespace dw {

class FxaaPass : public RenderPass {
public:
    explicit FxaaPass(KnobRegistry& knobs);
    const char* name() const override { return "fxaa"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"fxaa.result", OutputKind::Color, "the anti-aliased image (RGBA8)"}};
    }
    PassIO inputs(const KnobRegistry& knobs) const override;
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void resize(int width, int height, OutputRegistry& outputs) override;
    void execute(FrameContext& ctx) override;

private:
    BoolKnob enabled_, dofEnabled_;
    EnumKnob quality_;
    FloatKnob threshold_, thresholdMin_, subpixel_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::Texture result_;
    gl::Framebuffer fbo_;
    gl::Sampler linear_;
};

}  // namespace dw
