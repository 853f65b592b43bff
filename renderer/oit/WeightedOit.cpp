#include "renderer/oit/WeightedOit.h"

namespace dw {

namespace {
const int kEquation[] = {7, 8, 9, 10};
}

WeightedOit::WeightedOit(KnobRegistry& knobs) {
    weight_ = knobs.addEnum("oit.weight_function", {"eq7", "eq8", "eq9", "eq10"}, "eq7", "oit",
                            "weighted: McGuire and Bavoil 2013's weight w(z, a): eq7 a*clamp(10/(1e-5+(z/5)^2+(z/200)^6), "
                            "1e-2, 3e3); eq8 a*clamp(10/(1e-5+(z/10)^3+(z/200)^6), 1e-2, 3e3); eq9 "
                            "a*clamp(0.03/(1e-5+(z/200)^4), 1e-2, 3e3); eq10 a*max(1e-2, 3e3*(1-d)^3) (z view distance, "
                            "d window depth)");
}

std::string WeightedOit::description() const {
    return "weighted blended OIT (McGuire and Bavoil 2013): one unsorted pass into RGBA32F accumulation and R8 "
           "revealage, an approximation";
}

std::vector<OutputDecl> WeightedOit::outputs() const {
    return {
        {"oit.accum", OutputKind::HdrColor, "weighted: sum of w * premultiplied colour (rgb) and w * alpha (a), RGBA32F",
         texture2D(GL_RGBA32F), 4},
        {"oit.revealage", OutputKind::Scalar, "weighted: product of (1 - alpha), R8", texture2D(GL_R8), 1},
    };
}

void WeightedOit::setup(gl::ShaderLibrary& shaders) {
    resolve_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "oit/resolve.frag", .defines = {"RESOLVE_WEIGHTED"}});
}

void WeightedOit::render(OitFrame& f) {
    FrameContext& ctx = f.ctx;
    f.params.weightFunction = kEquation[ctx.knobs.get(weight_)];
    f.uploadParams();
    gl::Framebuffer& fbo = target_.get(ctx, {"oit.accum", "oit.revealage"}, {}, "oit weighted");
    fbo.bind();
    fbo.clearColor(0, 0, 0, 0, 0);
    fbo.clearColor(1, 1, 1, 1, 1);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
    f.drawTransparent(f.transparentProgram("METHOD_WEIGHTED"));
    glDisable(GL_BLEND);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    ctx.texture("oit.accum").bind(binding::OIT_ACCUM_TEXTURE);
    ctx.texture("oit.revealage").bind(binding::OIT_REVEALAGE_TEXTURE);
    f.compositeOverLBuffer(*resolve_);
    stats_ = "weight " + ctx.knobs.choice(weight_) + "; memory " +
             mebibytes(allocatedBytes(ctx, {"oit.accum", "oit.revealage", "oit.sample_count", "oit.overflow"}));
}

}  // namespace dw
