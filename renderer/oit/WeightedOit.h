#pragma once
// Weighted blended order-independent transparency (McGuire and Bavoil,
// "Weighted Blended Order-Independent Transparency", JCGT 2(2), 2013): one
// pass accumulates sum(w C_i) and sum(w a_i) in oit.accum (RGBA32F; the
// paper's RGBA16F overflowed at 65504 once colour x weight, up to 3e3,
// passed it; GL_ONE, GL_ONE) and prod(1 - a_i) in oit.revealage (R8,
// the paper's; GL_ZERO, GL_ONE_MINUS_SRC_COLOR); the composite is their
// eq. 6. The weight w(z, a) is the paper's eq. 7, 8, 9 or 10
// (oit.weight_function). No sorting and a fixed cost, but an approximation:
// its error against the linked list is in docs/transparency.md.
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/oit/OitMethod.h"

namespace dw {

class WeightedOit : public OitMethod {
public:
    explicit WeightedOit(KnobRegistry& knobs);
    const char* name() const override { return "weighted"; }
    std::string description() const override;
    std::vector<OutputDecl> outputs() const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void render(OitFrame& frame) override;
    std::string stats() const override { return stats_; }

private:
    EnumKnob weight_;
    gl::ShaderLibrary::Handle resolve_;
    TargetFramebuffer target_;
    std::string stats_;
};

}  // namespace dw
