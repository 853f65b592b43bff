#pragma once
// Dual depth peeling (Bavoil and Myers, "Order Independent Transparency with
// Dual Depth Peeling", NVIDIA 2008; seed 000 section 3.5.1 names it): each
// geometry pass peels two layers, the nearest and the farthest left, from a
// min-max depth range (RG32F, GL_MAX blending of (-f, f) with f the
// farness: 0 near, 1 far in either depth.mode); the nearest goes under the
// front layers so far (oit.dual_front_accum), the farthest over the back
// layers (oit.dual_back_accum). oit.peel_layers layers take
// ceil(oit.peel_layers / 2) passes after one pass for the initial range.
// oit.dual_count counts the layers found; the rest go to oit.overflow.
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/oit/OitMethod.h"

namespace dw {

class DualDepthPeelingOit : public OitMethod {
public:
    // Shares oit.peel_layers with depth_peeling (registered before it).
    explicit DualDepthPeelingOit(KnobRegistry& knobs) : layers_(knobs.requireInt("oit.peel_layers")) {}
    const char* name() const override { return "dual_depth_peeling"; }
    std::string description() const override;
    std::vector<OutputDecl> outputs() const override;
    void setup(gl::ShaderLibrary& shaders) override;
    bool needsFragmentCount() const override { return true; }
    void render(OitFrame& frame) override;
    std::string stats() const override { return stats_; }
    std::string lossCause() const override { return lossCause_; }

private:
    IntKnob layers_;
    gl::ShaderLibrary::Handle compose_, resolve_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer initTarget_, peelTarget_, accumTarget_;
    std::string stats_;
    std::string lossCause_;
};

}  // namespace dw
