#include "renderer/passes/GBufferDecodePass.h"

namespace dw {

void GBufferDecodePass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "gbuffer/decode.frag"});
}

void GBufferDecodePass::resize(int width, int height, OutputRegistry& outputs) {
    normal_ = gl::Texture::create2D(GL_RGBA32F, width, height);
    position_ = gl::Texture::create2D(GL_RGBA32F, width, height);
    normal_.setFilter(GL_NEAREST, GL_NEAREST);
    position_.setFilter(GL_NEAREST, GL_NEAREST);
    fbo_ = gl::Framebuffer::create("gbuffer decode");
    fbo_.attachColor(0, normal_);
    fbo_.attachColor(1, position_);
    fbo_.setDrawBuffers({0, 1});
    fbo_.checkComplete("G-buffer decode");
    outputs.bind("gbuffer.view_normal", &normal_, 4);
    outputs.bind("gbuffer.view_position", &position_, 4);
}

void GBufferDecodePass::execute(FrameContext& ctx) {
    ctx.outputs.find("gbuffer.normal")->texture->bind(0);
    ctx.outputs.find("gbuffer.depth")->texture->bind(1);
    fbo_.bind();
    program_->use();
    triangle_.draw();
}

}  // namespace dw
