#pragma once
// Geometry pass (seed 000 section 5.2, seed 002 pipeline step 1): renders the
// opaque scene once into the G-buffer. Reads the scene; writes gbuffer.albedo,
// gbuffer.normal, gbuffer.specular, gbuffer.emissive, gbuffer.occlusion (the
// materials' baked ambient occlusion, glTF occlusionTexture) and gbuffer.depth.
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"

namespace dw {

class GeometryPass : public RenderPass {
public:
    explicit GeometryPass(KnobRegistry& knobs);
    const char* name() const override { return "geometry"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry&) const override { return {}; }
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

private:
    gl::ShaderLibrary::Handle program_;
    TargetFramebuffer target_;
    std::string stats_;
};

}  // namespace dw
