#pragma once
// Geometry pass (seed 000 section 5.2, seed 002 pipeline step 1): renders the
// opaque scene once into the G-buffer. Reads the scene; writes gbuffer.albedo,
// gbuffer.normal, gbuffer.specular, gbuffer.emissive, gbuffer.occlusion (the
// materials' baked ambient occlusion, glTF occlusionTexture) and gbuffer.depth;
// with lighting.directional_in_gbuffer also gbuffer.directional, the
// directional lights without a shadow map shaded here (seed 000 section 3.2.1).
// With aa.method=msaa it draws into the multisampled G-buffer instead
// too (gbuffer.ms.*, the same formats, aa.samples samples; MsaaPass.h),
// after the ordinary one, which it draws as under every other method.
#include "renderer/graph/RenderPass.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "renderer/passes/MsaaPass.h"

namespace dw {

class GeometryPass : public RenderPass {
public:
    explicit GeometryPass(KnobRegistry& knobs);
    const char* name() const override { return "geometry"; }
    std::vector<OutputDecl> outputs() const override;
    // With lighting.directional_in_gbuffer: the light table (and so the
    // shadow pass, which marks the lights with maps) first.
    PassIO inputs(const KnobRegistry& knobs) const override;
    // gbuffer.albedo and gbuffer.specular as gbuffer.material_format says,
    // gbuffer.normal as gbuffer.normal_encoding, gbuffer.depth as gbuffer.depth_format.
    // The multisampled gbuffer.ms.* with aa.samples (capped) samples.
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    // gbuffer.ms.* only under aa.method=msaa (gbuffer.ms.directional also
    // with lighting.directional_in_gbuffer).
    bool allocates(const OutputDecl& output, const KnobRegistry& knobs) const override;
    void connect(const KnobRegistry& knobs) override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }
    // The gbuffer.texture_filter cap, when there was one this frame (one line).
    std::string frameWarning() const override { return capLine_; }

    // gbuffer.texture_filter's anisotropy: 1 for mipmap and base_level, N for anisoN.
    static float requestedAnisotropy(const std::string& textureFilter);
    // The line that says `textureFilter` (anisoN) was capped: to 1 on
    // llvmpipe (`llvmpipe`, with the reason: GpuScene::maxAnisotropy), else to
    // the device's GL_MAX_TEXTURE_MAX_ANISOTROPY `deviceMax`; empty when N fits.
    static std::string anisotropyCapLine(const std::string& textureFilter, float deviceMax, bool llvmpipe);

private:
    bool msaa(const KnobRegistry& knobs) const { return knobs.get(aaMethod_) == aaMsaa_; }
    const gl::Framebuffer& target(FrameContext& ctx, bool directional, bool multisampled);
    void drawScene(FrameContext& ctx, const gl::Framebuffer& fbo, bool directional, bool multisampled);

    EnumKnob aaMethod_;  // aa.method (AaMethod.h)
    int aaMsaa_ = -1;    // its choice msaa
    BoolKnob directional_;  // lighting.directional_in_gbuffer
    EnumKnob textureFilter_;  // gbuffer.texture_filter
    EnumKnob materialFormat_;  // gbuffer.material_format: srgb8, unorm16
    EnumKnob normalEncoding_;  // gbuffer.normal_encoding: kl16, oct16, oct8
    EnumKnob depthFormat_;     // gbuffer.depth_format: float32, unorm24
    gl::ShaderLibrary::Handle program_, directionalProgram_;
    TargetFramebuffer target_, directionalTarget_, msTarget_, msDirectionalTarget_;
    std::string stats_, capLine_;
};

}  // namespace dw
