#pragma once
// Lighting into the HDR L-buffer (seed 000 sections 3.2 and 5.2.1; seed 002
// step 4). Reads the G-buffer (and ssao.blurred and sky when they ran); writes lbuffer
// (RGBA16F) by additive blending: the ambient term and emission, each
// directional light as a full-screen pass, and point/spot lights by the chosen
// strategy:
//  stencil_volumes  sphere/cone volumes with the two-pass stencil test of
//                   seed 001 section 2.2 (counted on depth fail by default,
//                   which stays right with the camera inside a volume)
//  volumes          the volumes' back faces only, no stencil
//  fullscreen       every light over every pixel (the brute-force reference)
// All three run the same fragment shader with the in-volume test, so their
// images agree up to rounding (seed 000 section 6.1). When asked for, it also
// writes lighting.overlap: light-shader invocations per pixel, i.e. how many
// volumes passed the stencil test there (the cost map of the strategy).
// Lights with the shadow flag get a shadow map (renderer/ShadowMaps.h); the
// first four are published as shadow.map0..3 when asked for.
#include <vector>

#include "renderer/KnobRegistry.h"
#include "renderer/LightVolumeGeometry.h"
#include "renderer/ShadowMaps.h"
#include "renderer/RenderPass.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"

namespace dw {

class LightingPass : public RenderPass {
public:
    enum Strategy { StencilVolumes = 0, Volumes = 1, FullScreen = 2 };
    enum StencilCount { DepthFail = 0, DepthPass = 1 };

    explicit LightingPass(KnobRegistry& knobs);
    const char* name() const override { return "lighting"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry& knobs) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void resize(int width, int height, OutputRegistry& outputs) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

    static constexpr int kPublishedShadowMaps = 4;
    struct Counts {
        int directional = 0, volumes = 0, fullscreen = 0, frustumCulled = 0, belowThreshold = 0, shadowed = 0;
    };
    const Counts& lastCounts() const { return counts_; }
    // Shadow-map memory of the last frame, and what one map per light would take.
    std::size_t shadowBytesInUse() const { return shadows_.bytesInUse(); }
    std::size_t shadowBytesKeepingAll() const { return shadows_.bytesKeepingAll(); }

private:
    enum class Method { FullScreen, Volume, StencilVolume };
    void shade(FrameContext& ctx, int light, Method method, const LightVolumeGeometry* geometry, bool depthFail,
               bool counting);
    void publishShadowMap(FrameContext& ctx, int shadowIndex, ShadowMaps::Kind kind, int slot);

    FloatKnob threshold_;
    EnumKnob strategy_, stencilCount_, attenuation_;
    FloatKnob windowExponent_;
    BoolKnob frustumCull_, ambientSpecular_;

    struct LightPrograms {
        gl::ShaderLibrary::Handle fullscreen, volume;
    };
    gl::ShaderLibrary::Handle ambientProgram_, stencilProgram_;
    LightPrograms shade_, shadeCounting_;
    gl::FullscreenTriangle triangle_;
    LightVolumeGeometry sphere_, cone_;
    gl::Buffer lights_, params_;
    gl::Texture lbuffer_, overlap_, depthStencil_, white_;
    gl::Framebuffer fbo_;
    ShadowMaps shadows_;
    gl::Texture shadowViews_[kPublishedShadowMaps];
    gl::Framebuffer shadowViewFbos_[kPublishedShadowMaps];
    Counts counts_;
    std::string stats_;
};

}  // namespace dw
