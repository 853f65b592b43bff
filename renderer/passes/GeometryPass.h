#pragma once
// Geometry pass (seed 000 section 5.2, seed 002 pipeline step 1): renders the
// opaque scene once into the G-buffer. Reads the scene; writes gbuffer.albedo,
// gbuffer.normal, gbuffer.specular, gbuffer.emissive and gbuffer.depth.
#include "renderer/RenderPass.h"
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
    void resize(int width, int height, OutputRegistry& outputs) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

    const gl::Framebuffer& framebuffer() const { return fbo_; }
    const gl::Texture& depth() const { return depth_; }

private:
    gl::ShaderLibrary::Handle program_;
    gl::Texture albedo_, normal_, specular_, emissive_, depth_;
    gl::Framebuffer fbo_;
    std::string stats_;
};

}  // namespace dw
