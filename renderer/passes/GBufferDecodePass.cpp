#include "renderer/passes/GBufferDecodePass.h"

namespace dw {

void GBufferDecodePass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "gbuffer/decode.frag"});
}

void GBufferDecodePass::execute(FrameContext& ctx) {
    ctx.texture("gbuffer.normal").bind(0);
    ctx.texture("gbuffer.depth").bind(1);
    target_.get(ctx, {"gbuffer.view_normal", "gbuffer.view_position"}, {}, "G-buffer decode").bind();
    program_->use();
    triangle_.draw();
}

}  // namespace dw
