#pragma once
// Screen-space ambient occlusion, ao.method = ssao (seed 000 sections 4.6.3
// and 5.6, seed 002 section 5.1; seed 002 step 2). Reads gbuffer.depth and
// gbuffer.normal; writes ao.raw at ssao.resolution (full, 1/2 or 1/4, seed
// 000 table 6.4).
#include <glm/glm.hpp>
#include <vector>

#include "renderer/ao/AoMethod.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/Sampler.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/ssao.h"

namespace dw {

struct Bounds;

class SsaoMethod : public AoMethod {
public:
    explicit SsaoMethod(KnobRegistry& knobs);
    const char* name() const override { return "ssao"; }
    std::string description() const override;
    std::vector<std::string> knobNames() const override;
    int resolutionShift(const KnobRegistry& knobs) const override { return knobs.get(resolution_); }
    void setup(gl::ShaderLibrary& shaders) override;
    void run(FrameContext& ctx) override;
    // The scene's unit for ssao.radius_unit = scene_fraction: 10^round(log10(R / 10))
    // for the bounding radius R (1 for an empty scene), so scaling a scene by a
    // power of ten scales its SSAO radius with it.
    static float sceneUnit(const Bounds& bounds);
    // ssao.radius in world units under the current knobs.
    float worldRadius(const KnobRegistry& knobs, const Bounds& bounds) const;
    std::string stats() const override { return stats_; }

    // The AO resolution for a full resolution under `knobs`.
    glm::ivec2 aoSize(const KnobRegistry& knobs, int width, int height) const;
    // Kernel of `n` points in the unit ball, denser near the centre (deterministic).
    static std::vector<glm::vec4> kernel(int n);

private:
    BoolKnob rangeCheck_;
    IntKnob samples_;
    FloatKnob radius_, intensity_, bias_;
    EnumKnob resolution_, radiusUnit_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::SsaoParams> params_;
    gl::Texture noise_;
    gl::Sampler linearDepth_;  // depth between pixel centres (see ssao.frag)
    std::vector<glm::vec4> kernel_;  // kernel(ssao.samples), rebuilt when the count changes
    TargetFramebuffer target_;
    std::string stats_;
};

}  // namespace dw
