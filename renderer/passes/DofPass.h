#pragma once
// Depth of field (seed 004): blur from view depth around a focus distance,
// near and far, the near field as its own layer (Sousa 2013, Jimenez 2014:
// its blur dilated, its colour weighted by coverage and composited over the
// in-focus and far field; shaders/post/dof.frag). Reads the post chain's
// current image (the tone-mapped one unless a post pass comes before) and
// gbuffer.depth; writes dof.result (RGBA8), and when asked for dof.coc
// (signed circle of confusion in pixels) and dof.near_alpha (the near layer's
// coverage).
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/dof.h"

namespace dw {

class DofPass : public RenderPass {
public:
    explicit DofPass(KnobRegistry& knobs);
    const char* name() const override { return "dof"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"dof.result", OutputKind::Color, "the image with depth of field (RGBA8)", texture2D(GL_RGBA8)},
                {"dof.coc", OutputKind::Scalar, "signed circle of confusion in pixels (negative: nearer than the focus)",
                 texture2D(GL_R16F), 1, true},
                {"dof.near_alpha", OutputKind::Scalar,
                 "the near field's coverage, 0 to 1, with which its blurred layer is composited over the rest",
                 texture2D(GL_R16F), 1, true}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {{kCurrentImage, "gbuffer.depth"}, {}}; }
    void connect(const KnobRegistry& knobs) override { srgb_ = knobs.requireBool("tonemap.srgb"); }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;

private:
    BoolKnob enabled_, near_, far_, srgb_;
    FloatKnob focus_, range_, radius_;
    IntKnob samples_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::DofParams> params_;
    TargetFramebuffer result_, coc_, nearAlpha_;
};

}  // namespace dw
