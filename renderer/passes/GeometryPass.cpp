#include "renderer/passes/GeometryPass.h"

#include "renderer/GpuScene.h"
#include "renderer/scene/Scene.h"

namespace dw {

GeometryPass::GeometryPass(KnobRegistry&) {}

std::vector<OutputDecl> GeometryPass::outputs() const {
    return {
        {"gbuffer.albedo", OutputKind::Color, "diffuse colour (sRGB8); alpha holds the pixel type (0 background, 1 surface)"},
        {"gbuffer.normal", OutputKind::NormalKL, "view-space normal, Kircher-Lawrance encoded in RG16_SNORM"},
        {"gbuffer.specular", OutputKind::Color, "specular colour (sRGB8); alpha = log2(Blinn-Phong exponent)/11"},
        {"gbuffer.emissive", OutputKind::HdrColor, "emitted radiance (R11G11B10F)"},
        {"gbuffer.depth", OutputKind::Depth, "window-space depth (DEPTH32F_STENCIL8)"},
    };
}

void GeometryPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "geometry.vert", .fragment = "geometry.frag"});
}

void GeometryPass::resize(int width, int height, OutputRegistry& outputs) {
    albedo_ = gl::Texture::create2D(GL_SRGB8_ALPHA8, width, height);
    normal_ = gl::Texture::create2D(GL_RG16_SNORM, width, height);
    specular_ = gl::Texture::create2D(GL_SRGB8_ALPHA8, width, height);
    emissive_ = gl::Texture::create2D(GL_R11F_G11F_B10F, width, height);
    depth_ = gl::Texture::create2D(GL_DEPTH32F_STENCIL8, width, height);
    // Nearest: a G-buffer value between pixels means nothing. (SSAO reads
    // depth between pixel centres through its own linear sampler.)
    for (gl::Texture* t : {&albedo_, &normal_, &specular_, &emissive_, &depth_}) t->setFilter(GL_NEAREST, GL_NEAREST);
    fbo_ = gl::Framebuffer::create("gbuffer");
    fbo_.attachColor(0, albedo_);
    fbo_.attachColor(1, normal_);
    fbo_.attachColor(2, specular_);
    fbo_.attachColor(3, emissive_);
    fbo_.attachDepth(depth_);
    fbo_.setDrawBuffers({0, 1, 2, 3});
    fbo_.checkComplete("G-buffer");
    outputs.bind("gbuffer.albedo", &albedo_, 4);
    outputs.bind("gbuffer.normal", &normal_, 2);
    outputs.bind("gbuffer.specular", &specular_, 4);
    outputs.bind("gbuffer.emissive", &emissive_, 3);
    outputs.bind("gbuffer.depth", &depth_, 1);
}

void GeometryPass::execute(FrameContext& ctx) {
    fbo_.bind();
    fbo_.clearColor(0, 0, 0, 0, 0);
    fbo_.clearColor(1, 0, 0, 0, 0);
    fbo_.clearColor(2, 0, 0, 0, 0);
    fbo_.clearColor(3, 0, 0, 0, 0);
    fbo_.clearDepthStencil(1.0f, 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // Albedo and specular are sRGB targets: encode the shader's linear values
    // on write, so sampling them decodes back to linear.
    glEnable(GL_FRAMEBUFFER_SRGB);
    program_->use();
    // Blended materials are drawn as opaque until a transparency pass exists.
    ctx.gpu.draw(*program_, GpuScene::Filter::All);
    stats_ = std::to_string(ctx.gpu.draws().size()) + " draws, " + std::to_string(ctx.gpu.triangleCount()) + " triangles";
}

}  // namespace dw
