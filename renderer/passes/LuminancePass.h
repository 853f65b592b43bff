#pragma once
// Image statistics for tone mapping (seed 000 section 5.3.1; seed 002 step 6):
// log-average luminance exp(mean(log(delta + L))) and max luminance (L_white)
// by GPU reduction, never read back by the CPU. Reads lbuffer (under SSAA:
// per output pixel, the mean of its rendered pixels); writes
// luminance.stats (1x1 RGBA32F: log-average, max, mean, finite pixel count).
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/luminance.h"

namespace dw {

class LuminancePass : public RenderPass {
public:
    explicit LuminancePass(KnobRegistry& knobs);
    const char* name() const override { return "luminance"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"luminance.stats", OutputKind::Scalar,
                 "1x1 RGBA32F: log-average luminance, max luminance, mean luminance, finite pixel count"}};
    }
    PassIO inputs(const KnobRegistry& knobs) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void resize(int width, int height, OutputRegistry& outputs) override;
    void execute(FrameContext& ctx) override;

    // Reduces any RGB(A) float texture into `stats` (exposed for tests). With a
    // depth texture, pixels at depth 1 (background) are left out. `footprint`
    // k > 1 (SSAA's factor): the statistics of the k x k box means, the output
    // pixels' area means (as the reference's), not of the rendered pixels.
    void reduce(const gl::Texture& hdr, float delta, const gl::Texture* depthMask = nullptr, int footprint = 1);
    const gl::Texture& statsTexture() const { return stats_; }

private:
    static int ssaaFootprint(const FrameContext& ctx, const gl::Texture& lbuffer);

    FloatKnob delta_;
    EnumKnob background_;
    int exclude_ = 0;  // luminance.background = exclude
    gl::ShaderLibrary::Handle first_, next_, finalize_;
    gl::Buffer ping_, pong_;
    gl::ParamBuffer<gpu::LuminanceParams> params_;
    gl::Texture stats_;
};

}  // namespace dw
