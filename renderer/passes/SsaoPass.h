#pragma once
// Screen-space ambient occlusion (seed 000 sections 4.6.3 and 5.6, seed 002
// section 5.1; seed 002 step 2). Reads gbuffer.depth and gbuffer.normal;
// writes ssao.raw at the AO resolution (full, 1/2 or 1/4, seed 000 table 6.4).
#include <glm/glm.hpp>
#include <vector>

#include "renderer/KnobRegistry.h"
#include "renderer/RenderPass.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/Sampler.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"

namespace dw {

class SsaoPass : public RenderPass {
public:
    enum Resolution { Full = 0, Half = 1, Quarter = 2 };
    explicit SsaoPass(KnobRegistry& knobs);
    const char* name() const override { return "ssao"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"ssao.raw", OutputKind::Scalar, "ambient accessibility before blurring, 1 = open (R16F, at the AO resolution)"}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {{"gbuffer.depth", "gbuffer.normal"}, {}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void resize(int width, int height, OutputRegistry& outputs) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

    // The AO resolution for a full resolution under `knobs`.
    glm::ivec2 aoSize(const KnobRegistry& knobs, int width, int height) const;
    // Kernel of `n` points in the unit ball, denser near the centre (deterministic).
    static std::vector<glm::vec4> kernel(int n);

private:
    void allocate(int width, int height);
    BoolKnob enabled_, rangeCheck_;
    IntKnob samples_;
    FloatKnob radius_, intensity_, bias_;
    EnumKnob resolution_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::Buffer params_;
    gl::Texture noise_, ao_;
    gl::Sampler linearDepth_;  // depth between pixel centres (see ssao.frag)
    std::vector<glm::vec4> kernel_;  // kernel(ssao.samples), rebuilt when the count changes
    gl::Framebuffer fbo_;
    OutputRegistry* outputs_ = nullptr;
    std::string stats_;
};

}  // namespace dw
