#include "renderer/passes/SkyboxPass.h"

#include <cmath>
#include <glm/glm.hpp>

#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {
struct SkyParamsGpu {
    glm::ivec4 modes{0};
    glm::vec4 zenith{0.0f}, horizon{0.0f}, ground{0.0f}, sunDir{0.0f}, sunColor{0.0f};
};
enum ShaderKind { kColor = 0, kProcedural = 1, kEquirect = 2, kCube = 3 };
}  // namespace

SkyboxPass::SkyboxPass(KnobRegistry& knobs) {
    mode_ = knobs.addEnum("skybox.mode", {"scene", "color", "procedural", "environment"}, FromScene, "skybox",
                          "the sky: what the scene specifies, its flat background colour, a procedural sky, or its "
                          "environment map");
    intensity_ = knobs.addFloat("skybox.intensity", 1.0, 0.0, 1000.0, "skybox", "multiplier on the sky's radiance", "",
                                false, true);
    rotation_ = knobs.addFloat("skybox.rotation", 0.0, -180.0, 180.0, "skybox", "rotation of the environment about +Y", "deg");
}

int SkyboxPass::resolvedKind(const KnobRegistry& knobs, const Scene& scene) const {
    const bool hasEnvironment = scene.sky.equirect.width > 0 || !scene.sky.cubeFaces.empty();
    int mode = knobs.get(mode_);
    if (mode == FromScene)
        mode = scene.sky.kind == Sky::Kind::Color ? Color : (scene.sky.kind == Sky::Kind::Procedural ? Procedural : Environment);
    if (mode == Color) return kColor;
    if (mode == Procedural) return kProcedural;
    if (!hasEnvironment) return -1;
    return scene.sky.cubeFaces.empty() ? kEquirect : kCube;
}

std::string SkyboxPass::skipReason(const KnobRegistry& knobs, const Scene& scene) const {
    const int kind = resolvedKind(knobs, scene);
    if (kind == kColor) return "the sky is the flat background colour (skybox.mode)";
    if (kind < 0) return "the scene has no environment map (skybox.mode = environment)";
    return {};
}

void SkyboxPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "sky/sky.frag"});
    params_ = gl::Buffer::create(sizeof(SkyParamsGpu), nullptr, true, "sky params");
    dummy2D_ = gl::Texture::create2D(GL_RGBA16F, 1, 1);
    dummyCube_ = gl::Texture::createCube(GL_RGBA16F, 1);
}

void SkyboxPass::execute(FrameContext& ctx) {
    const Sky& s = ctx.scene.sky;
    const int kind = resolvedKind(ctx.knobs, ctx.scene);
    SkyParamsGpu p;
    p.modes = glm::ivec4(kind, 0, 0, 0);
    p.zenith = glm::vec4(s.zenith, ctx.knobs.get(intensity_) * s.intensity);
    p.horizon = glm::vec4(s.horizon, glm::radians(ctx.knobs.get(rotation_) + s.rotationDegrees));
    p.ground = glm::vec4(s.ground, std::cos(glm::radians(s.sunSizeDegrees * 0.5f)));
    // The sun: the first enabled directional light, seen as a disc.
    for (const Light& l : ctx.scene.lights)
        if (l.enabled && l.type == LightType::Directional) {
            p.sunDir = glm::vec4(-glm::normalize(l.direction), 1.0f);
            p.sunColor = glm::vec4(l.intensity * 40.0f, 0.0f);
            break;
        }
    params_.update(0, sizeof(p), &p);
    params_.bindBase(GL_UNIFORM_BUFFER, binding::kPassUbo);
    ctx.texture("gbuffer.depth").bind(0);
    const gl::Texture* env = ctx.gpu.environment();
    (kind == kEquirect && env ? *env : dummy2D_).bind(1);
    (kind == kCube && env ? *env : dummyCube_).bind(2);
    target_.get(ctx, {"sky"}, {}, "sky").bind();
    program_->use();
    triangle_.draw();
    static const char* names[] = {"colour", "procedural", "equirectangular environment", "cube map environment"};
    stats_ = std::string(names[kind]) + (kind >= kEquirect ? " (" + s.environmentSource + ")" : "");
}

}  // namespace dw
