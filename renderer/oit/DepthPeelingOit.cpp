#include "renderer/oit/DepthPeelingOit.h"

namespace dw {

DepthPeelingOit::DepthPeelingOit(KnobRegistry& knobs) {
    layers_ = knobs.addInt("oit.peel_layers", 8, 1, 64, "oit",
                           "depth_peeling: layers peeled, one geometry pass each (not capped by MSAA); the fragments "
                           "behind the last are lost and counted in oit.overflow",
                           "layers", true);
}

std::string DepthPeelingOit::description() const {
    return "depth peeling (seed 000 5.8): oit.peel_layers geometry passes, each keeping the nearest fragment behind the "
           "last layer, composited front to back";
}

std::vector<OutputDecl> DepthPeelingOit::outputs() const {
    return {
        {"oit.peel_color", OutputKind::HdrColor, "depth_peeling: the last layer peeled, premultiplied (RGBA32F)",
         texture2D(GL_RGBA32F), 4},
        {"oit.peel_depth", OutputKind::Depth, "depth_peeling: the last layer's depth (DEPTH32F)",
         texture2D(GL_DEPTH_COMPONENT32F), 1},
        {"oit.peel_prev_depth", OutputKind::Depth, "depth_peeling: the layer before's depth, peeled against (DEPTH32F)",
         texture2D(GL_DEPTH_COMPONENT32F), 1},
        {"oit.peel_accum", OutputKind::HdrColor,
         "depth_peeling: the layers so far, front to back: rgb premultiplied colour, a transmittance (RGBA32F)",
         texture2D(GL_RGBA32F), 4},
        {"oit.peel_count", OutputKind::Count, "depth_peeling: layers found per pixel (R32UI)", texture2D(GL_R32UI), 1},
    };
}

void DepthPeelingOit::setup(gl::ShaderLibrary& shaders) {
    compose_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "oit/peel_compose.frag"});
    resolve_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "oit/resolve.frag", .defines = {"RESOLVE_PEEL"}});
}

void DepthPeelingOit::render(OitFrame& f) {
    FrameContext& ctx = f.ctx;
    const int layers = ctx.knobs.get(layers_);
    const DepthConvention depth = ctx.depth();
    const gl::Texture& count = ctx.texture("oit.peel_count");
    count.clearUint(0);
    count.bindImage(binding::OIT_PEEL_LAYERS_IMAGE, GL_READ_WRITE);
    gl::Framebuffer& accum = accumTarget_.get(ctx, {"oit.peel_accum"}, {}, "oit peel accumulation");
    accum.clearColor(0, 0, 0, 0, 1);
    gl::Framebuffer& prev = prevTarget_.get(ctx, {}, "oit.peel_prev_depth", "oit peel previous depth");
    prev.clearDepth(depth.nearDepth());
    gl::Framebuffer& layer = layerTarget_.get(ctx, {"oit.peel_color"}, "oit.peel_depth", "oit peel layer");
    const gl::Texture& color = ctx.texture("oit.peel_color");
    const gl::Texture& layerDepth = ctx.texture("oit.peel_depth");
    const gl::Texture& prevDepth = ctx.texture("oit.peel_prev_depth");
    const gl::Program& peel = f.transparentProgram("METHOD_PEEL");
    for (int k = 0; k < layers; ++k) {
        // Only the first pass counts the fragments (all of them reach it).
        f.params.peelLayer = k;
        f.params.countFragments = k == 0 ? 1 : 0;
        f.uploadParams();
        layer.bind();
        layer.clearColor(0, 0, 0, 0, 0);
        layer.clearDepth(depth.farDepth());
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(depth.nearer());
        glDepthMask(GL_TRUE);
        prevDepth.bind(binding::OIT_PREVIOUS_DEPTH_TEXTURE);
        f.drawTransparent(peel);
        glDisable(GL_DEPTH_TEST);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);

        accum.bind();
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
        color.bind(binding::OIT_LAYER_COLOR_TEXTURE);
        layerDepth.bind(binding::OIT_LAYER_DEPTH_TEXTURE);
        compose_->use();
        triangle_.draw();
        glDisable(GL_BLEND);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        glCopyImageSubData(layerDepth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, prevDepth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.width,
                           ctx.height, 1);
    }
    ctx.texture("oit.peel_accum").bind(binding::OIT_PEEL_ACCUM_TEXTURE);
    f.compositeOverLBuffer(*resolve_);
    lossCause_ = "depth_peeling peels " + std::to_string(layers) +
                 (layers == 1 ? " layer" : " layers") + " (oit.peel_layers); a fragment behind them, or at exactly the depth of one peeled, is lost";
    stats_ = std::to_string(layers) + (layers == 1 ? " layer" : " layers") + " peeled (" + std::to_string(layers) + " geometry passes); memory " +
             mebibytes(allocatedBytes(ctx, {"oit.peel_color", "oit.peel_depth", "oit.peel_prev_depth", "oit.peel_accum",
                                            "oit.peel_count", "oit.sample_count", "oit.overflow"}));
}

}  // namespace dw
