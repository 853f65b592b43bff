#include "renderer/passes/GeometryPass.h"

#include "renderer/knobs/KnobRegistry.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Scene.h"

namespace dw {

GeometryPass::GeometryPass(KnobRegistry& knobs) {
    knobs.addEnum("depth.mode", {"reversed", "conventional"}, 0, "depth",
                  "depth mapping of every depth buffer (G-buffer, shadow maps): reversed (near 1, far 0, GL_GREATER; "
                  "float depth keeps about 1e-7 relative precision at every distance) or conventional (near 0, far 1, "
                  "GL_LESS; precision spent near the camera)");
}

std::vector<OutputDecl> GeometryPass::outputs() const {
    return {
        {"gbuffer.albedo", OutputKind::Color, "diffuse colour (sRGB8); alpha holds the pixel type (0 background, 1 surface)",
         texture2D(GL_SRGB8_ALPHA8), 4},
        {"gbuffer.normal", OutputKind::NormalKL, "view-space normal, Kircher-Lawrance encoded in RG16_SNORM",
         texture2D(GL_RG16_SNORM), 2},
        {"gbuffer.specular", OutputKind::Color, "specular colour (sRGB8); alpha = log2(Blinn-Phong exponent)/11",
         texture2D(GL_SRGB8_ALPHA8), 4},
        {"gbuffer.emissive", OutputKind::HdrColor, "emitted radiance (R11G11B10F)", texture2D(GL_R11F_G11F_B10F), 3},
        {"gbuffer.depth", OutputKind::Depth, "window-space depth (DEPTH32F_STENCIL8)", texture2D(GL_DEPTH32F_STENCIL8), 1},
    };
}

void GeometryPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "geometry.vert", .fragment = "geometry.frag"});
}

void GeometryPass::execute(FrameContext& ctx) {
    // Outputs are nearest-filtered: a G-buffer value between pixels means
    // nothing (SSAO reads depth between pixel centres through its own sampler).
    const gl::Framebuffer& fbo =
        target_.get(ctx, {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.emissive"}, "gbuffer.depth", "G-buffer");
    fbo.bind();
    fbo.clearColor(0, 0, 0, 0, 0);
    fbo.clearColor(1, 0, 0, 0, 0);
    fbo.clearColor(2, 0, 0, 0, 0);
    fbo.clearColor(3, 0, 0, 0, 0);
    const DepthConvention depth = ctx.depth();
    fbo.clearDepthStencil(depth.farDepth(), 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth.nearer());
    // Albedo and specular are sRGB targets: encode the shader's linear values
    // on write, so sampling them decodes back to linear.
    glEnable(GL_FRAMEBUFFER_SRGB);
    program_->use();
    // Blended materials are drawn as opaque until a transparency pass exists.
    ctx.gpu.draw(*program_, GpuScene::Filter::All);
    stats_ = std::to_string(ctx.gpu.draws().size()) + " draws, " + std::to_string(ctx.gpu.triangleCount()) + " triangles";
}

}  // namespace dw
