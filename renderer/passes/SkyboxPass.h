#pragma once
// Skybox (seed 004 "Skybox"): the sky's radiance where the G-buffer holds no
// geometry (seed 000 section 5.2's pixel type). Reads gbuffer.depth and the
// scene's sky; writes sky (RGBA16F), which the lighting pass puts into the
// L-buffer's background pixels. The sky is a procedural gradient with a sun,
// an equirectangular HDR/EXR image or a cube map (through OpenImageIO).
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/sky.h"

namespace dw {

struct Sky;

class SkyboxPass : public RenderPass {
public:
    explicit SkyboxPass(KnobRegistry& knobs);
    const char* name() const override { return "skybox"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"sky", OutputKind::HdrColor, "sky radiance where no geometry is, 0 elsewhere (RGBA16F)", texture2D(GL_RGBA16F)}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {{"gbuffer.depth"}, {}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

private:
    // gpu::SKY_KIND_*, or -1 when the sky is an environment map the scene lacks.
    int resolvedKind(const KnobRegistry& knobs, const Scene& scene) const;
    EnumKnob mode_;
    int modeFromScene_ = 0, modeColor_ = 0, modeProcedural_ = 0;  // skybox.mode's choices the pass branches on
    FloatKnob intensity_, rotation_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::SkyParams> params_;
    gl::Texture dummy2D_, dummyCube_;
    TargetFramebuffer target_;
    std::string stats_;
};

}  // namespace dw
