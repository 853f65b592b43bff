#pragma once
// The stencil-routed A-buffer (seed 000 sections 3.5.2 and 5.9; Myers and
// Bavoil 2007): a multisample colour (RGBA32F) and depth-stencil
// (DEPTH32F_STENCIL8) target of N samples, N = oit.samples capped by what
// the device lists for both formats (glGetInternalformativ GL_SAMPLES: 4 on
// llvmpipe). Each sample's stencil is set to 2 + its index through the
// sample mask; the transparent fragments are then drawn with
// glStencilFunc(GL_EQUAL, 2) and glStencilOp(GL_DECR x3), so the k-th
// fragment of a pixel lands in sample k-1, its depth written with
// GL_ALWAYS; fragments behind the opaque surface are discarded in the
// shader (a depth-fail op would waste or double a slot). A full-screen
// resolve reads every sample, sorts by depth and blends back to front.
// At a silhouette (a fragment covering some samples only) the samples'
// stencil values fall out of step, the method's known edge artefact.
// GL_DECR clamps at 0, so the overflow (fragments past N) comes from the
// fragment counter: oit.overflow = oit.sample_count - N where positive.
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/oit/OitMethod.h"

namespace dw {

class StencilRoutedOit : public OitMethod {
public:
    explicit StencilRoutedOit(KnobRegistry& knobs);
    const char* name() const override { return "abuffer"; }
    std::string description() const override;
    std::vector<OutputDecl> outputs() const override;
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    bool needsFragmentCount() const override { return true; }
    void render(OitFrame& frame) override;
    std::string stats() const override { return stats_; }
    std::string lossCause() const override { return lossCause_; }
    // The samples the target gets under `knobs`: oit.samples capped by the device.
    int samples(const KnobRegistry& knobs) const;
    // What the device offers for RGBA32F and DEPTH32F_STENCIL8 (0 before setup).
    int deviceCap() const { return cap_; }

private:
    IntKnob samples_;
    int cap_ = 0;
    bool cpuRasterizer_ = false;  // llvmpipe: routing with GL_MULTISAMPLE on (see render)
    gl::ShaderLibrary::Handle resolve_, stencilInit_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer target_;
    std::string stats_;
    std::string lossCause_;
};

}  // namespace dw
