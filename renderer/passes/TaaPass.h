#pragma once
// Temporal anti-aliasing (aa.method=taa; Karis 2014): each frame's projection
// is jittered by a sub-pixel offset from the Halton(2,3) sequence
// (RenderPass::sampling; kJitterPeriod offsets, then again), and this pass,
// last in the post chain, blends the display image with its history:
// last frame's result read where this pixel's surface was then (reprojected
// from gbuffer.depth and the camera's motion, both frames unjittered),
// clamped into this frame's 3x3 neighbourhood (min/max in YCoCg) and mixed
// by aa.taa_blend (the current frame's weight: an exponential moving
// average). Writes taa.result (RGBA8) and taa.rejected (R8: 1 where the
// history was thrown away: off screen, the clamp moved it by more than
// aa.taa_reject, or no history yet). shaders/post/taa.frag; docs/antialiasing.md.
#include <glm/glm.hpp>
#include <string>

#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/Sampler.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "renderer/knobs/KnobRegistry.h"
#include "shaders/params/taa.h"

namespace dw {

class TaaPass : public RenderPass {
public:
    static constexpr int kJitterPeriod = 16;
    // The jitter of frame `frameIndex` in pixels, each component in [-0.5, 0.5):
    // Halton(2,3) point (frameIndex mod kJitterPeriod) + 1, minus 0.5.
    static glm::vec2 jitter(std::uint64_t frameIndex);

    explicit TaaPass(KnobRegistry& knobs);
    const char* name() const override { return "taa"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry&) const override { return {{kCurrentImage, "gbuffer.depth"}, {}, {}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    FrameSampling sampling(const KnobRegistry& knobs, std::uint64_t frameIndex, int width, int height) override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

private:
    // Whether last frame's result can be reprojected into this one; says why not in stats_.
    bool historyUsable(const FrameContext& ctx);
    void keepHistory(const FrameContext& ctx, const glm::dmat4& unjitteredClip);

    EnumKnob method_;
    FloatKnob blend_, reject_;
    glm::vec2 jitter_{0.0f};           // this frame's (sampling())
    glm::dmat4 previousClip_{1.0};     // last frame's world -> clip, unjittered (absolute world)
    std::uint64_t previousFrame_ = ~std::uint64_t(0);
    const Scene* previousScene_ = nullptr;
    gl::Texture history_;
    std::string stats_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer target_;
    gl::Sampler linear_, nearest_;
    gl::ParamBuffer<gpu::TaaParams> params_;
};

}  // namespace dw
