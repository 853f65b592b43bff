#pragma once
// Depth peeling (seed 000 section 5.8; Everitt 2001), front to back: pass k
// draws the transparent surfaces with the depth test keeping the nearest
// fragment behind layer k-1 (oit.peel_prev_depth, compared in the shader),
// into oit.peel_color and oit.peel_depth; a full-screen pass then adds the
// layer under the ones before in oit.peel_accum (C += T c, T *= 1 - a).
// oit.peel_layers passes (not capped by MSAA); oit.peel_count counts the
// layers found per pixel, and the fragments past them go to oit.overflow.
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/oit/OitMethod.h"

namespace dw {

class DepthPeelingOit : public OitMethod {
public:
    explicit DepthPeelingOit(KnobRegistry& knobs);
    const char* name() const override { return "depth_peeling"; }
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
    TargetFramebuffer layerTarget_, accumTarget_, prevTarget_;
    std::string stats_;
    std::string lossCause_;
};

}  // namespace dw
