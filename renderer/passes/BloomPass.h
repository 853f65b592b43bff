#pragma once
// Bloom (seed 000 sections 4.3 and 5.4, seed 002 section 3.2, steps 7-8):
// the L-buffer at half resolution with a threshold relative to the average
// luminance subtracted, then either Ferko's average of its mip levels or the
// dual-filter mip chain of Jimenez 2014 (13-tap down, tent up). Reads lbuffer
// and luminance.stats; writes bloom.bright, bloom.mip1..6 and bloom.result,
// which the tone mapper composites.
#include <vector>

#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/bloom.h"

namespace dw {

class BloomPass : public RenderPass {
public:
    static constexpr int kMaxLevels = 6;
    static constexpr int kMinLevelTexels = 8;  // the coarsest level used is at least this wide and high
    explicit BloomPass(KnobRegistry& knobs);
    const char* name() const override { return "bloom"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry&) const override { return {{"lbuffer", "luminance.stats"}, {}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void connect(const KnobRegistry& knobs) override { nanGuard_ = knobs.requireBool("tonemap.nan_guard"); }
    void setup(gl::ShaderLibrary& shaders) override;
    void resize(int width, int height, OutputRegistry& outputs) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

private:
    struct Target {
        gl::Texture texture;
        gl::Framebuffer fbo;
    };
    void makeTarget(Target& t, int w, int h, int levels, const char* label);
    void drawInto(const gl::Framebuffer& fbo, int w, int h);
    BoolKnob enabled_, nanGuard_;
    EnumKnob method_;
    int mipSum_ = 0;  // bloom.method = mip_sum
    FloatKnob threshold_, intensity_;
    IntKnob levels_;
    EnumKnob composite_;
    gl::ShaderLibrary::Handle brightProgram_, mipsum_, down_, up_, scale_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::BloomParams> params_;
    TargetFramebuffer bright_, result_;
    Target down_chain_[kMaxLevels + 1], up_chain_[kMaxLevels + 1];
    std::string stats_;
};

}  // namespace dw
