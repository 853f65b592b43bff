#pragma once
// On-demand decoded G-buffer views for inspection and tests. Reads
// gbuffer.normal and gbuffer.depth; writes gbuffer.view_normal (decoded,
// seed 000 eqs. 3.2-3.3) and gbuffer.view_position (reconstructed from depth,
// seed 000 section 3.1). Culled unless something asks for these outputs.
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"

namespace dw {

class GBufferDecodePass : public RenderPass {
public:
    explicit GBufferDecodePass(KnobRegistry&) {}
    const char* name() const override { return "gbuffer_decode"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"gbuffer.view_normal", OutputKind::Vector, "decoded view-space normal (RGBA32F, w = 1 on surfaces)",
                 texture2D(GL_RGBA32F)},
                {"gbuffer.view_position", OutputKind::Vector, "view-space position reconstructed from depth (RGBA32F)",
                 texture2D(GL_RGBA32F)}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {{"gbuffer.normal", "gbuffer.depth"}, {}}; }
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;

private:
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer target_;
};

}  // namespace dw
