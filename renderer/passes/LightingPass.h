#pragma once
// Lighting into the HDR L-buffer (seed 000 sections 3.2 and 5.2.1; seed 002
// step 4). Reads the G-buffer, the light table (lights.table) and, when they
// ran, ao.filtered and sky; writes lbuffer (RGBA32F) by additive blending:
// the ambient term, emission and the sky first (shaders/lighting/
// ambient.glsl), then each directional (and unbounded) light as a
// full-screen pass, then the bounded point and spot lights by the strategy
// lighting.strategy names (renderer/lighting/LightingStrategy.h:
// stencil_volumes, volumes, fullscreen, tiled (a compute pass writing by
// image load/store), clustered, and any registered). A strategy whose own
// pass makes the first write (LightingStrategy::writesFirstRadiance: tiled
// with lighting.tile_ambient) goes first instead, and the directional lights
// after it.
// Shadow maps come from the shadow pass (FrameContext::shadows),
// rendered just before their light when maps are reused. Also writes
// lbuffer.depth (the G-buffer depth copied, with the stencil the volumes
// used; forward passes after lighting test against it, seed 003) and, when
// asked for, lighting.overlap: light-shader invocations per pixel, and the
// strategies' own outputs (lighting.tile_counts, lighting.cluster_counts).
// On demand, lighting.shadow (R32F): the shadow factor as the CPU reference's
// shadow buffer defines it (ReferenceRenderer.h: the luminance of the
// shadow-mapped lights' radiance with their shadow lookups over that without
// them; 1 where none reaches and on the sky), one additive full-screen draw
// per shadow-mapped light (its map rendered again when maps are reused) into
// a pass-owned RG32F sum, then divided (shaders/lighting/shadow_*.frag).
// With aa.method=msaa (MsaaPass.h) it shades the ordinary G-buffer as
// always, then each sample of the edge pixels aa.edges marks through the
// same strategy, and box-resolves the radiance (shadeEdgeSamples).
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/lighting/LightingStrategy.h"
#include "renderer/passes/MsaaPass.h"
#include "shaders/params/lighting.h"

namespace dw {

class LightingPass : public RenderPass {
public:
    explicit LightingPass(KnobRegistry& knobs);
    ~LightingPass() override;
    const char* name() const override { return "lighting"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry& knobs) const override;
    void connect(const KnobRegistry& knobs) override;
    // lbuffer.depth in gbuffer.depth's format (gbuffer.depth_format).
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }
    std::string frameWarning() const override { return msaaWarning_; }

    struct Counts {
        int directional = 0, directionalInGBuffer = 0, volumes = 0, batches = 0, fullscreen = 0, frustumCulled = 0, belowThreshold = 0, shadowed = 0;
        int grid = 0;  // shaded from lists: tiles, clusters (tiled, clustered) or per object (forward)
        const char* gridWhere = kGridInTilesOrClusters;
    };
    const Counts& lastCounts() const { return counts_; }
    // The strategy the last frame used (what auto picked, under auto).
    const std::string& lastStrategy() const { return lastStrategy_; }
    // lighting.auto_coverage and lighting.auto_cluster_coverage defaults:
    // measured on llvmpipe at 640x360 (docs/bench.md, "auto").
    static constexpr double kAutoCoverage = 9.0;
    static constexpr double kAutoClusterCoverage = 1e6;  // never: tiled was faster at every coverage measured
    // The strategies, in the order of lighting.strategy's choices.
    const std::vector<std::unique_ptr<LightingStrategy>>& strategies() const { return strategies_->all(); }

private:
    // The strategy lighting.strategy names, or under auto the one
    // chooseLightingStrategy picks from `lights` (the frame's bounded lights);
    // sets autoWhy_.
    // lighting.shadow, after the lights (see the header's opening).
    void writeShadowFactor(FrameContext& ctx, const LightTable& table, const std::function<void()>& bindInputs);
    LightingStrategy& pickStrategy(const FrameContext& ctx, const std::vector<const LightTableEntry*>& lights);
    // Shades the G-buffer as it stands into lbuffer (ambient, screen lights,
    // the strategy's lights); counts_ and the optional outputs as ctx wants them.
    LightingStrategy& shadeGBuffer(FrameContext& ctx);
    std::vector<const LightTableEntry*> sortLights(const LightTable& table, const std::vector<int>& shadedInGBuffer,
                                                   std::vector<const LightTableEntry*>& bounded);
    void addStrategyCounts(const StrategyCounts& sc);
    // The pass's parameter block for this frame, uploaded; returns the
    // directional lights the G-buffer pass shaded (light-table rows).
    std::vector<int> uploadParams(const FrameContext& ctx, const LightTable& table);
    // aa.method=msaa: the N samples of the edge pixels, each copied into the
    // G-buffer and shaded, the radiance averaged; the G-buffer put back after.
    void shadeEdgeSamples(FrameContext& ctx, const LightingStrategy& strategy);
    void describe(const FrameContext& ctx, const LightingStrategy& strategy);

    std::optional<MethodSet<LightingStrategy>> strategies_;  // lighting.strategy's, and its choice auto
    EnumKnob attenuation_;
    int windowed_ = 0;  // lighting.attenuation = windowed
    FloatKnob windowExponent_;
    BoolKnob ambientSpecular_;
    IntKnob volumeSubdivisions_;
    EnumKnob ambientOcclusion_;  // both, baked, screen
    int aoBaked_ = 0, aoScreen_ = 0;
    EnumKnob aoMethod_;         // ao.method (AoPass's)
    int aoGtao_ = 0;            // its choice gtao
    BoolKnob gtaoMultibounce_;  // gtao.multibounce (GtaoMethod's): applied here, where the albedo is

    gl::ShaderLibrary::Handle ambientProgram_;
    LightShading shading_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::LightingParams> params_;
    gl::Texture white_;
    gl::ShaderLibrary::Handle shadowSumsProgram_, shadowResolveProgram_;
    gl::Texture shadowSums_;  // RG32F: lit and unshadowed luminance (lighting.shadow)
    gl::Framebuffer shadowSumsTarget_;
    int shadowSumsWidth_ = 0, shadowSumsHeight_ = 0;
    TargetFramebuffer shadowTarget_;
    TargetFramebuffer target_, countingTarget_;
    Counts counts_;
    std::string stats_, autoWhy_, lastStrategy_;
    FloatKnob autoCoverage_, autoClusterCoverage_;
    BoolKnob directionalInGBuffer_;  // declared by the geometry pass
    EnumKnob depthFormat_;           // gbuffer.depth_format, declared by the geometry pass
    EnumKnob aaMethod_;              // aa.method (AaMethod.h)
    int aaMsaa_ = -1;                // its choice msaa
    MsaaSampleCopy msaaCopy_;
    MsaaResolve msaaResolve_;
    std::string msaaLine_;
    std::string msaaWarning_;        // MSAA under a strategy that cannot shade samples (frameWarning)           // what MSAA shaded this frame, for the statistics line
};

}  // namespace dw
