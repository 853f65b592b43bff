#pragma once
// Supersampling (aa.method=ssaa; seed 000 section 3.3): the pipeline renders
// every frame-sized resource (G-buffer, L-buffer, tone-mapped image) at
// aa.ssaa_factor (2 or 4) times the output size per axis (RenderPass::sampling),
// and this pass, the last of the post chain, filters the display image down
// with a box filter over each output pixel's square (shaders/post/ssaa_resolve.frag,
// in linear light): ssaa.result (RGBA8, the output size). On demand,
// ssaa.lbuffer: the HDR L-buffer filtered down the same way (RGBA32F), the
// area mean of radiance that the reference's --spp N box average estimates.
// Memory: the supersampled frame is held to kMaxPixels and kMaxSide; a larger
// one halves the factor (said in stats() and frameWarning()). docs/antialiasing.md.
#include <string>

#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/knobs/KnobRegistry.h"
#include "shaders/params/ssaa.h"

namespace dw {

class SsaaPass : public RenderPass {
public:
    // The largest supersampled frame: 3840x2160 pixels (the G-buffer,
    // L-buffer and post targets of a 4K frame), and 16384 per side (GL 4.5's
    // least GL_MAX_TEXTURE_SIZE).
    static constexpr long long kMaxPixels = 3840LL * 2160LL;
    static constexpr int kMaxSide = 16384;
    // The factor used at `width` x `height` for the requested one: halved until the frame fits.
    static int cappedFactor(int requested, int width, int height);

    explicit SsaaPass(KnobRegistry& knobs);
    const char* name() const override { return "ssaa"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry&) const override { return {{kCurrentImage}, {"lbuffer"}, {}}; }
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    FrameSampling sampling(const KnobRegistry& knobs, std::uint64_t frameIndex, int width, int height) override;
    void connect(const KnobRegistry& knobs) override { srgb_ = knobs.requireBool("tonemap.srgb"); }
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }
    std::string frameWarning() const override { return warning_; }

private:
    void resolve(FrameContext& ctx, const gl::Texture& source, const std::string& target, bool srgb);

    EnumKnob method_, factorKnob_;
    BoolKnob srgb_;
    int factor_ = 1;  // this frame's factor (after the cap)
    std::string stats_, warning_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer result_, lbuffer_;
    gl::ParamBuffer<gpu::SsaaParams> params_;
};

}  // namespace dw
