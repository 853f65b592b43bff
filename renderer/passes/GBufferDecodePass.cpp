#include "renderer/passes/GBufferDecodePass.h"

namespace dw {

void GBufferDecodePass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "gbuffer/decode.frag"});
}

void GBufferDecodePass::execute(FrameContext& ctx) {
    ctx.texture("gbuffer.normal").bind(binding::GBUFFER_DECODE_NORMAL_TEXTURE);
    ctx.texture("gbuffer.depth").bind(binding::GBUFFER_DECODE_DEPTH_TEXTURE);
    target_.get(ctx, {"gbuffer.view_normal", "gbuffer.view_position"}, {}, "G-buffer decode").bind();
    program_->use();
    triangle_.draw();
}

}  // namespace dw
