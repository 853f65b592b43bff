#include "renderer/passes/TonemapPass.h"

#include <glm/glm.hpp>

#include "renderer/GpuScene.h"

namespace dw {

namespace {
struct TonemapParamsGpu {
    glm::ivec4 modes{0};
    glm::vec4 values{0.0f};
};
}  // namespace

TonemapPass::TonemapPass(KnobRegistry& knobs) {
    operator_ = knobs.addEnum("tonemap.operator", {"simple", "reinhard"}, Reinhard, "tonemap",
                              "simple L/(1+L) (seed 000 eq. 4.1) or Reinhard's global operator with log-average "
                              "luminance and L_white (eqs. 4.3, 4.4)");
    key_ = knobs.addFloat("tonemap.key", 0.18, 0.01, 2.0, "tonemap",
                          "Reinhard key value a: the luminance the log-average maps to (eq. 4.3)");
    autoWhite_ = knobs.addBool("tonemap.auto_white", true, "tonemap",
                               "L_white = the image's highest luminance, from the GPU max-reduction (seed 000 5.3.1)");
    white_ = knobs.addFloat("tonemap.white", 4.0, 0.01, 1e4, "tonemap",
                            "manual L_white (scaled luminance mapped to white) when auto_white is off", "", false, true);
    exposure_ = knobs.addFloat("tonemap.exposure", 0.0, -10.0, 10.0, "tonemap",
                               "exposure applied to the L-buffer before the operator", "EV");
    srgb_ = knobs.addBool("tonemap.srgb", true, "tonemap", "encode the output with the sRGB transfer curve");
}

PassIO TonemapPass::inputs(const KnobRegistry& knobs) const {
    PassIO io;
    io.inputs = {"lbuffer"};
    if (knobs.get(operator_) == Reinhard) io.inputs.push_back("luminance.stats");
    return io;
}

void TonemapPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "tonemap/tonemap.frag"});
    params_ = gl::Buffer::create(sizeof(TonemapParamsGpu), nullptr, true, "tonemap params");
}

void TonemapPass::resize(int width, int height, OutputRegistry& outputs) {
    final_ = gl::Texture::create2D(GL_RGBA8, width, height);
    fbo_ = gl::Framebuffer::create("final");
    fbo_.attachColor(0, final_);
    fbo_.setDrawBuffers({0});
    fbo_.checkComplete("final image");
    outputs.bind("final", &final_, 4);
}

void TonemapPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    TonemapParamsGpu p;
    p.modes = glm::ivec4(k.get(operator_), k.get(autoWhite_) ? 1 : 0, k.get(srgb_) ? 1 : 0, 0);
    p.values = glm::vec4(k.get(key_), k.get(white_), k.get(exposure_), 0.0f);
    params_.update(0, sizeof(p), &p);
    params_.bindBase(GL_UNIFORM_BUFFER, binding::kPassUbo);
    ctx.outputs.find("lbuffer")->texture->bind(0);
    if (ctx.produced("luminance.stats")) ctx.outputs.find("luminance.stats")->texture->bind(1);
    fbo_.bind();
    program_->use();
    triangle_.draw();
}

}  // namespace dw
