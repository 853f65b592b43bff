#pragma once
// Ground-truth ambient occlusion, ao.method = gtao (Jimenez, Wu, Pesce and
// Jarabo, "Practical Real-Time Strategies for Accurate Indirect Occlusion",
// 2016; Intel's XeGTAO is the reference implementation): horizon search in
// gtao.slices screen-space slices, gtao.steps depth samples per side, the
// paper's closed-form cosine-weighted visibility (shaders/ao/gtao.frag).
// Reads gbuffer.depth and gbuffer.normal; writes ao.raw at gtao.resolution
// (full or half). gtao.thin_occluders: a sample that looks thin (the
// shaded point's own surface is back just beyond it along the slice, as
// beside a pole before a wall) shades the angle it subtends, its measured
// width over its distance, instead of raising the horizon as an infinitely
// thick one (shaders/ao/gtao.frag thinWidth, docs/ao.md "Thin occluders"). Denoised (gtao.denoise) by the shared cross-bilateral
// filter (ssao_blur.*), by its own edge-aware 5x5 filter
// (shaders/ao/gtao_denoise.frag, from gtao.noisy into ao.raw), or not at all.
// gtao.bent_normals: also writes gtao.bent_normal, the cosine-weighted mean
// unoccluded direction (view space, unit length; the paper's bent normal,
// derived in docs/ao.md). gtao.multibounce is read by the lighting pass,
// which applies the paper's multi-bounce fit with the G-buffer albedo.
#include <glm/glm.hpp>

#include "renderer/ao/AoMethod.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/Sampler.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "shaders/params/gtao.h"

namespace dw {

struct Bounds;

class GtaoMethod : public AoMethod {
public:
    explicit GtaoMethod(KnobRegistry& knobs);
    const char* name() const override { return "gtao"; }
    std::string description() const override;
    std::vector<std::string> knobNames() const override;
    int resolutionShift(const KnobRegistry& knobs) const override { return knobs.get(resolution_); }
    bool sharedBlur(const KnobRegistry& knobs) const override { return knobs.get(denoise_) == shared_; }
    std::vector<OutputDecl> outputs() const override;
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    bool allocates(const OutputDecl& output, const KnobRegistry& knobs) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void run(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

    // gtao.radius in world units under the current knobs (gtao.radius_unit
    // as ssao.radius_unit: world, or the scene's power-of-ten unit).
    float worldRadius(const KnobRegistry& knobs, const Bounds& bounds) const;

private:
    IntKnob slices_, steps_;
    FloatKnob radius_, falloff_, thickness_, thinOccluders_;
    EnumKnob radiusUnit_, resolution_, denoise_;
    BoolKnob multibounce_, bentNormals_;
    int shared_ = 0, edgeAware_ = 0;
    gl::ShaderLibrary::Handle program_, denoiseProgram_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::GtaoParams> params_;
    gl::Sampler linearDepth_;
    TargetFramebuffer target_, noisyTarget_, bentTarget_, bentNoisyTarget_;
    std::string stats_;
};

}  // namespace dw
