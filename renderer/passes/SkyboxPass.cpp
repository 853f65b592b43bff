#include "renderer/passes/SkyboxPass.h"

#include <cmath>
#include <glm/glm.hpp>

#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Scene.h"

namespace dw {

SkyboxPass::SkyboxPass(KnobRegistry& knobs) {
    mode_ = knobs.addEnum("skybox.mode", {"scene", "color", "procedural", "environment"}, "scene", "skybox",
                          "the sky: what the scene specifies, its flat background colour, a procedural sky, or its "
                          "environment map");
    modeFromScene_ = knobs.choiceIndex(mode_, "scene");
    modeColor_ = knobs.choiceIndex(mode_, "color");
    modeProcedural_ = knobs.choiceIndex(mode_, "procedural");
    intensity_ = knobs.addFloat("skybox.intensity", 1.0, 0.0, 1000.0, "skybox", "multiplier on the sky's radiance", "",
                                false, true);
    rotation_ = knobs.addFloat("skybox.rotation", 0.0, -180.0, 180.0, "skybox", "rotation of the environment about +Y", "deg");
}

int SkyboxPass::resolvedKind(const KnobRegistry& knobs, const Scene& scene) const {
    const bool hasEnvironment = scene.sky.equirect.width > 0 || !scene.sky.cubeFaces.empty();
    const int mode = knobs.get(mode_);
    const bool color = mode == modeFromScene_ ? scene.sky.kind == Sky::Kind::Color : mode == modeColor_;
    const bool procedural = mode == modeFromScene_ ? scene.sky.kind == Sky::Kind::Procedural : mode == modeProcedural_;
    if (color) return gpu::SKY_KIND_COLOR;
    if (procedural) return gpu::SKY_KIND_PROCEDURAL;
    if (!hasEnvironment) return -1;
    return scene.sky.cubeFaces.empty() ? gpu::SKY_KIND_EQUIRECT : gpu::SKY_KIND_CUBE;
}

std::string SkyboxPass::skipReason(const KnobRegistry& knobs, const Scene& scene) const {
    const int kind = resolvedKind(knobs, scene);
    if (kind == gpu::SKY_KIND_COLOR) return "the sky is the flat background colour (skybox.mode)";
    if (kind < 0) return "the scene has no environment map (skybox.mode = environment)";
    return {};
}

void SkyboxPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "sky/sky.frag"});
    params_.create();
    dummy2D_ = gl::Texture::create2D(GL_RGBA16F, 1, 1);
    dummyCube_ = gl::Texture::createCube(GL_RGBA16F, 1);
}

void SkyboxPass::execute(FrameContext& ctx) {
    const Sky& s = ctx.scene.sky;
    const int kind = resolvedKind(ctx.knobs, ctx.scene);
    gpu::SkyParams p{};
    p.kind = kind;
    p.intensity = ctx.knobs.get(intensity_) * s.intensity;
    p.rotation = glm::radians(ctx.knobs.get(rotation_) + s.rotationDegrees);
    p.zenith = s.zenith;
    p.horizon = s.horizon;
    p.ground = s.ground;
    p.cosSunRadius = std::cos(glm::radians(s.sunSizeDegrees * 0.5f));
    // The sun: the first enabled directional light, seen as a disc.
    for (const Light& l : ctx.scene.lights)
        if (l.enabled && l.type == LightType::Directional) {
            p.hasSun = 1;
            p.sunDirection = -glm::normalize(l.direction);
            p.sunColor = l.intensity * 40.0f;
            break;
        }
    params_.upload(p, binding::PASS_UBO);
    ctx.texture("gbuffer.depth").bind(binding::SKY_DEPTH_TEXTURE);
    const gl::Texture* env = ctx.gpu.environment();
    (kind == gpu::SKY_KIND_EQUIRECT && env ? *env : dummy2D_).bind(binding::SKY_EQUIRECT_TEXTURE);
    (kind == gpu::SKY_KIND_CUBE && env ? *env : dummyCube_).bind(binding::SKY_CUBE_TEXTURE);
    target_.get(ctx, {"sky"}, {}, "sky").bind();
    program_->use();
    triangle_.draw();
    const bool environment = kind == gpu::SKY_KIND_EQUIRECT || kind == gpu::SKY_KIND_CUBE;
    stats_ = std::string(kind == gpu::SKY_KIND_PROCEDURAL ? "procedural"
                         : kind == gpu::SKY_KIND_EQUIRECT ? "equirectangular environment"
                         : kind == gpu::SKY_KIND_CUBE     ? "cube map environment"
                                                          : "colour") +
             (environment ? " (" + s.environmentSource + ")" : "");
}

}  // namespace dw
