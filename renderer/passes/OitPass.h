#pragma once
// Order-independent transparency (issue 21; seed 000 sections 3.4-3.5 and
// 5.8-5.9, seed 002 section 4, seed 003 section 3.4). Reads gbuffer.depth
// (transparent fragments behind the opaque surface are discarded against
// it), lights.table (and the shadow maps when every map was kept) and
// lbuffer.depth; adds into lbuffer (a modify edge: bloom and tone mapping
// see the transparent surfaces). The blended materials, kept out of the
// G-buffer, shadow maps and SSAO, are forward-shaded with the light table
// and composited by the method oit.method names (renderer/oit/OitMethod.h:
// linked_list, abuffer, depth_peeling, dual_depth_peeling, weighted,
// forward_sorted). Writes
// oit.sample_count (every transparent fragment that reached the pixel,
// stored or lost) and oit.overflow (lost), and each method's own outputs.
// Skipped, with the reason, when the scene has no blended material.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/oit/OitMethod.h"
#include "shaders/params/lighting.h"
#include "shaders/params/oit.h"

namespace dw {

class OitPass : public RenderPass {
public:
    explicit OitPass(KnobRegistry& knobs);
    ~OitPass() override;
    const char* name() const override { return "oit"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry& knobs) const override;
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    bool allocates(const OutputDecl& output, const KnobRegistry& knobs) const override;
    void connect(const KnobRegistry& knobs) override;
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    // Skipped when every blended object's bounding sphere is outside the view frustum.
    std::string viewSkipReason(const KnobRegistry& knobs, const Scene& scene, const CameraUniforms& camera) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }
    // "lost N of M transparent fragments (where: the method's limits)" when
    // the last frame's method lost any; empty otherwise.
    std::string frameWarning() const override { return warning_; }

    const std::vector<std::unique_ptr<OitMethod>>& methods() const { return methods_->all(); }
    // The blended instances the last frame drew.
    std::size_t lastDraws() const { return lastDraws_; }
    // The last frame's transparent fragments lost (summed oit.overflow) and
    // counted (summed oit.sample_count; 0 where the method counts none).
    std::uint64_t lastLost() const { return lastLost_; }
    std::uint64_t lastArrived() const { return lastArrived_; }

private:
    const gl::Program& transparentProgram(const std::string& method, bool shadowed);
    // The method's lost and arrived fragments, summed on the GPU, read back; the warning when any were lost.
    void readLostTotal(const OitMethod& method);

    std::optional<MethodSet<OitMethod>> methods_;  // oit.method's
    BoolKnob enabled_;
    EnumKnob attenuation_;
    int windowed_ = 0;
    FloatKnob windowExponent_;
    BoolKnob ambientSpecular_;
    gl::ShaderLibrary* shaders_ = nullptr;
    gl::ParamBuffer<gpu::LightingParams> lighting_;
    gl::ParamBuffer<gpu::OitParams> params_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer composite_;
    gl::Buffer lostTotal_;  // (lost, arrived), summed by shaders/oit/resolve.frag
    std::string stats_, warning_;
    std::size_t lastDraws_ = 0;
    std::uint64_t lastLost_ = 0, lastArrived_ = 0;
};

}  // namespace dw
