#pragma once
// The light table (DESIGN.md "Resources and strategies"; seed 001 section 2.2
// for the radius): every enabled light that can reach the threshold, its
// volume and radius (I_max att(r) = lighting.threshold), its view-space
// position and direction, and whether its volume meets the view frustum.
// Reads the scene; writes lights.table (an SSBO of LightGpu rows, binding
// LIGHT_SSBO) and hands the CPU side to later passes (FrameContext::lightTable).
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/lighting/LightTable.h"

namespace dw {

class LightTablePass : public RenderPass {
public:
    explicit LightTablePass(KnobRegistry& knobs);
    const char* name() const override { return "lights"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry&) const override { return {}; }
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

    const LightTable& table() const { return table_; }

private:
    FloatKnob threshold_;
    BoolKnob frustumCull_;
    gl::Buffer buffer_;
    LightTable table_;
    std::string stats_;
};

}  // namespace dw
