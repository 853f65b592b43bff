#include "renderer/oit/StencilRoutedOit.h"

#include <algorithm>

#include "renderer/gl/DebugOutput.h"
#include "renderer/gl/DeviceLimits.h"

namespace dw {

StencilRoutedOit::StencilRoutedOit(KnobRegistry& knobs) {
    samples_ = knobs.addInt("oit.samples", 8, 1, gpu::OIT_MAX_SAMPLES, "oit",
                            "abuffer: samples per pixel, the layers the stencil-routed A-buffer holds; capped by what the "
                            "device offers for RGBA32F and DEPTH32F_STENCIL8 (4 on llvmpipe, 8 or more on GPUs)",
                            "samples", true);
}

std::string StencilRoutedOit::description() const {
    return "stencil-routed A-buffer (seed 000 5.9): oit.samples layers per pixel in a multisample target, sorted in a "
           "resolve; the fragments past them are counted in oit.overflow";
}

std::vector<OutputDecl> StencilRoutedOit::outputs() const {
    return {
        {"oit.abuffer", OutputKind::HdrColor,
         "abuffer: each sample one layer, premultiplied colour and alpha in arrival order (RGBA32F x oit.samples)",
         textureMultisample(GL_RGBA32F, 4), 4},
        {"oit.abuffer_depth", OutputKind::Depth,
         "abuffer: each sample's window depth and routing stencil (DEPTH32F_STENCIL8 x oit.samples)",
         textureMultisample(GL_DEPTH32F_STENCIL8, 4), 1},
    };
}

int StencilRoutedOit::samples(const KnobRegistry& knobs) const {
    const int want = knobs.get(samples_);
    return cap_ > 0 ? std::min(want, cap_) : want;
}

ResourceDesc StencilRoutedOit::resource(const OutputDecl& output, const KnobRegistry& knobs) const {
    ResourceDesc d = output.resource;
    d.samples = samples(knobs);
    return d;
}

void StencilRoutedOit::setup(gl::ShaderLibrary& shaders) {
    cap_ = std::min(gl::maxMultisampleSamples({GL_RGBA32F, GL_DEPTH32F_STENCIL8}), gpu::OIT_MAX_SAMPLES);
    gl::GlInfo info;
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    info.renderer = renderer ? renderer : "";
    cpuRasterizer_ = gl::isCpuRasterizer(info);
    resolve_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "oit/resolve.frag", .defines = {"RESOLVE_ABUFFER"}});
    stencilInit_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "oit/stencil_init.frag"});
}

void StencilRoutedOit::render(OitFrame& f) {
    FrameContext& ctx = f.ctx;
    const int n = samples(ctx.knobs);
    f.params.samples = n;
    f.uploadParams();
    gl::Framebuffer& fbo = target_.get(ctx, {"oit.abuffer"}, "oit.abuffer_depth", "oit A-buffer");
    fbo.bind();
    fbo.clearColor(0, 0, 0, 0, 0);
    fbo.clearDepthStencil(ctx.depth().farDepth(), 0);
    glEnable(GL_MULTISAMPLE);

    // Each sample's stencil to 2 + its index, one full-screen draw per sample.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_SAMPLE_MASK);
    glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
    stencilInit_->use();
    for (int i = 0; i < n; ++i) {
        glSampleMaski(0, 1u << i);
        glStencilFunc(GL_ALWAYS, 2 + i, 0xFF);
        triangle_.draw();
    }
    glSampleMaski(0, ~0u);
    glDisable(GL_SAMPLE_MASK);
    // Routing rasterises per sample (GL_MULTISAMPLE stays on: llvmpipe then
    // tests each sample's stencil; with it off only one). A pixel on the edge
    // two triangles of a surface share gets a fragment from each, covering
    // complementary samples: each sample still steps down once and the slot
    // at 2 is written once; the shader counts only the fragment covering
    // sample 0, so oit.sample_count stays one per surface.

    // Routing: only the sample at 2 takes the fragment; every sample steps down.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 2, 0xFF);
    glStencilOp(GL_DECR, GL_DECR, GL_DECR);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    // Routing needs every fragment to cover all samples (one stencil step
    // per surface in every sample). With GL_MULTISAMPLE off, GL rasterises
    // with full coverage where the pixel centre is covered, which is what
    // a GPU gets here. llvmpipe then tests only one sample's stencil, so
    // there it stays on: where two surfaces' triangles split a pixel's
    // samples differently (a closed double-sided object's edges), a sample
    // can take a second fragment of one surface and lose another
    // (docs/transparency.md, "Known limits").
    if (!cpuRasterizer_) glDisable(GL_MULTISAMPLE);
    f.drawTransparent(f.transparentProgram("METHOD_ABUFFER"));
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_MULTISAMPLE);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    ctx.texture("oit.abuffer").bind(binding::OIT_SAMPLES_TEXTURE);
    ctx.texture("oit.abuffer_depth").bind(binding::OIT_SAMPLE_DEPTH_TEXTURE);
    f.compositeOverLBuffer(*resolve_);
    const int want = ctx.knobs.get(samples_);
    lossCause_ = "abuffer keeps " + std::to_string(n) + " per pixel (oit.samples = " + std::to_string(want) +
                 (want > n ? ", capped by the device" : "") + "), the first to arrive";
    stats_ = std::to_string(n) + " samples" +
             (want > n ? " (oit.samples = " + std::to_string(want) + " capped: the device offers " + std::to_string(cap_) +
                             " for RGBA32F and DEPTH32F_STENCIL8)"
                       : "") +
             "; memory " + mebibytes(allocatedBytes(ctx, {"oit.abuffer", "oit.abuffer_depth", "oit.sample_count", "oit.overflow"}));
}

}  // namespace dw
