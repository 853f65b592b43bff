#include "renderer/inspect/ForwardPreview.h"
#include "renderer/gl/MemoryLedger.h"

#include "renderer/scene/GpuScene.h"
#include "renderer/gl/FullscreenTriangle.h"

namespace dw {

void ForwardPreview::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "forward/preview.vert", .fragment = "forward/preview.frag"});
}

const gl::Texture& ForwardPreview::render(const GpuScene& gpu, int width, int height, Mode mode, DepthConvention depth) {
    if (!color_ || color_.width() != width || color_.height() != height) {
        gl::MemoryOwner owner("forward preview");
        color_ = gl::Texture::create2D(GL_RGBA8, width, height);
        depth_ = gl::Texture::create2D(GL_DEPTH32F_STENCIL8, width, height);
        fbo_ = gl::Framebuffer::create("forward preview");
        fbo_.attachColor(0, color_);
        fbo_.attachDepth(depth_);
        fbo_.setDrawBuffers({0});
        fbo_.checkComplete("forward preview");
    }
    gl::resetPipelineState(width, height);
    fbo_.bind();
    const float bg = mode == Mode::Wireframe ? 0.02f : 0.12f;
    fbo_.clearColor(0, bg, bg, bg * 1.2f, 1.0f);
    fbo_.clearDepthStencil(depth.farDepth(), 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth.nearer());
    if (mode == Mode::Wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    program_->use();
    program_->set(2, mode == Mode::Wireframe ? 1 : 0);
    gpu.draw(*program_, GpuScene::Filter::All);
    gl::resetPipelineState(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return color_;
}

}  // namespace dw
