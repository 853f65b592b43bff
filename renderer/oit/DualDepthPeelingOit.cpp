#include "renderer/oit/DualDepthPeelingOit.h"

namespace dw {

std::string DualDepthPeelingOit::description() const {
    return "dual depth peeling (Bavoil and Myers 2008): the nearest and the farthest layer per geometry pass, "
           "ceil(oit.peel_layers / 2) passes after a min-max depth pass";
}

std::vector<OutputDecl> DualDepthPeelingOit::outputs() const {
    return {
        {"oit.dual_depth", OutputKind::Vector, "dual_depth_peeling: (-nearest, farthest) farness left after the last pass (RG32F)",
         texture2D(GL_RG32F), 2},
        {"oit.dual_prev_depth", OutputKind::Vector, "dual_depth_peeling: the range the last pass peeled (RG32F)",
         texture2D(GL_RG32F), 2},
        {"oit.dual_front", OutputKind::HdrColor, "dual_depth_peeling: the last pass's nearest layer (RGBA32F)",
         texture2D(GL_RGBA32F), 4},
        {"oit.dual_back", OutputKind::HdrColor, "dual_depth_peeling: the last pass's farthest layer (RGBA32F)",
         texture2D(GL_RGBA32F), 4},
        {"oit.dual_front_accum", OutputKind::HdrColor,
         "dual_depth_peeling: the front layers, front to back: rgb colour, a transmittance (RGBA32F)", texture2D(GL_RGBA32F), 4},
        {"oit.dual_back_accum", OutputKind::HdrColor,
         "dual_depth_peeling: the back layers, back to front: rgb colour, a transmittance (RGBA32F)", texture2D(GL_RGBA32F), 4},
        {"oit.dual_count", OutputKind::Count, "dual_depth_peeling: layers found per pixel (R32UI)", texture2D(GL_R32UI), 1},
        {"oit.dual_claims", OutputKind::Scalar,
         "dual_depth_peeling: the last pass's claims per pixel (bit 0 the nearest layer taken, bit 1 the farthest; a "
         "second fragment at exactly a taken depth is lost, not merged; R32UI)",
         texture2D(GL_R32UI), 1},
    };
}

void DualDepthPeelingOit::setup(gl::ShaderLibrary& shaders) {
    compose_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "oit/dual_compose.frag"});
    resolve_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "oit/resolve.frag", .defines = {"RESOLVE_DUAL"}});
}

void DualDepthPeelingOit::render(OitFrame& f) {
    FrameContext& ctx = f.ctx;
    const int layers = ctx.knobs.get(layers_);
    const int passes = (layers + 1) / 2;
    const gl::Texture& count = ctx.texture("oit.dual_count");
    count.clearUint(0);
    count.bindImage(binding::OIT_PEEL_LAYERS_IMAGE, GL_READ_WRITE);
    const gl::Texture& depth = ctx.texture("oit.dual_depth");
    const gl::Texture& prev = ctx.texture("oit.dual_prev_depth");
    auto copyRange = [&] {
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
        glCopyImageSubData(depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, prev.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.width, ctx.height, 1);
    };

    // The initial range, counting every fragment.
    gl::Framebuffer& init = initTarget_.get(ctx, {"oit.dual_depth"}, {}, "oit dual range");
    init.bind();
    init.clearColor(0, -2, -2, 0, 0);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
    f.params.countFragments = 1;
    f.uploadParams();
    f.drawTransparent(f.transparentProgram("METHOD_DUAL_INIT"));
    copyRange();

    gl::Framebuffer& accum = accumTarget_.get(ctx, {"oit.dual_front_accum", "oit.dual_back_accum"}, {}, "oit dual accumulation");
    accum.clearColor(0, 0, 0, 0, 1);
    accum.clearColor(1, 0, 0, 0, 1);
    gl::Framebuffer& peel = peelTarget_.get(ctx, {"oit.dual_depth", "oit.dual_front", "oit.dual_back"}, {}, "oit dual peel");
    f.params.countFragments = 0;
    f.uploadParams();
    const gl::Program& program = f.transparentProgram("METHOD_DUAL");
    const gl::Texture& claims = ctx.texture("oit.dual_claims");
    claims.bindImage(binding::OIT_DUAL_CLAIMS_IMAGE, GL_READ_WRITE);
    for (int k = 0; k < passes; ++k) {
        claims.clearUint(0);
        // An odd layer count: the last pass keeps its nearest layer only, so N layers means N.
        f.params.frontOnly = k == passes - 1 && layers % 2 == 1 ? 1 : 0;
        f.uploadParams();
        peel.bind();
        peel.clearColor(0, -2, -2, 0, 0);
        peel.clearColor(1, 0, 0, 0, 0);
        peel.clearColor(2, 0, 0, 0, 0);
        glEnable(GL_BLEND);
        glBlendEquation(GL_MAX);
        prev.bind(binding::OIT_PREVIOUS_DEPTH_TEXTURE);
        f.drawTransparent(program);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);

        accum.bind();
        glBlendEquation(GL_FUNC_ADD);
        glBlendFuncSeparatei(0, GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
        glBlendFuncSeparatei(1, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
        ctx.texture("oit.dual_front").bind(binding::OIT_FRONT_LAYER_TEXTURE);
        ctx.texture("oit.dual_back").bind(binding::OIT_BACK_LAYER_TEXTURE);
        compose_->use();
        triangle_.draw();
        copyRange();
    }
    f.params.frontOnly = 0;
    glDisable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    ctx.texture("oit.dual_front_accum").bind(binding::OIT_FRONT_ACCUM_TEXTURE);
    ctx.texture("oit.dual_back_accum").bind(binding::OIT_BACK_ACCUM_TEXTURE);
    f.compositeOverLBuffer(*resolve_);
    lossCause_ = "dual_depth_peeling peels " + std::to_string(layers) +
                 (layers == 1 ? " layer" : " layers") + " (oit.peel_layers); a fragment between them, or at exactly the depth of one peeled, is lost";
    stats_ = std::to_string(layers) + (layers == 1 ? " layer" : " layers") + " in " + std::to_string(passes + 1) + " geometry passes; memory " +
             mebibytes(allocatedBytes(ctx, {"oit.dual_depth", "oit.dual_prev_depth", "oit.dual_front", "oit.dual_back",
                                            "oit.dual_front_accum", "oit.dual_back_accum", "oit.dual_count", "oit.dual_claims",
                                            "oit.sample_count", "oit.overflow"}));
}

}  // namespace dw
