#pragma once
// Depth of field (seed 004): blur from view depth around a focus distance,
// near and far. Reads tonemap.result and gbuffer.depth; writes dof.result
// (RGBA8) and dof.coc (signed circle of confusion in pixels, when asked for).
#include "renderer/KnobRegistry.h"
#include "renderer/RenderPass.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"

namespace dw {

class DofPass : public RenderPass {
public:
    explicit DofPass(KnobRegistry& knobs);
    const char* name() const override { return "dof"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"dof.result", OutputKind::Color, "the tone-mapped image with depth of field (RGBA8)"},
                {"dof.coc", OutputKind::Scalar, "signed circle of confusion in pixels (negative: nearer than the focus)"}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {{"tonemap.result", "gbuffer.depth"}, {}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void resize(int width, int height, OutputRegistry& outputs) override;
    void execute(FrameContext& ctx) override;

private:
    BoolKnob enabled_, near_, far_, srgb_;
    FloatKnob focus_, range_, radius_;
    IntKnob samples_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::Buffer params_;
    gl::Texture result_, coc_;
    gl::Framebuffer resultFbo_, cocFbo_;
};

}  // namespace dw
