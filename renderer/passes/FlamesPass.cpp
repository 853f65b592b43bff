#include "renderer/passes/FlamesPass.h"

#include <algorithm>
#include <cmath>

#include "renderer/gl/Texture.h"
#include "renderer/scene/FlameParticles.h"
#include "renderer/scene/Scene.h"

namespace dw {

glm::vec3 blackbodyColour(double kelvin) {
    // Planck: B(l, T) = 2hc^2 / l^5 / (exp(hc / (l k T)) - 1); the constant factor cancels.
    const double c2 = 1.438776877e-2;  // hc / k, m K
    const double lambda[3] = {610e-9, 550e-9, 465e-9};
    double b[3];
    for (int i = 0; i < 3; ++i) b[i] = 1.0 / (std::pow(lambda[i], 5.0) * std::expm1(c2 / (lambda[i] * kelvin)));
    const double top = std::max({b[0], b[1], b[2]});
    return {static_cast<float>(b[0] / top), static_cast<float>(b[1] / top), static_cast<float>(b[2] / top)};
}

double flameTemperature(float age) {
    const double a = std::clamp(static_cast<double>(age), 0.0, 1.0);
    return kFlameBirthKelvin + (kFlameDeathKelvin - kFlameBirthKelvin) * a;
}

FlamesPass::FlamesPass(KnobRegistry& knobs) {
    enabled_ = knobs.addBool("flames.enabled", true, "flames",
                             "draw the fire's flame particles (seed 004); off: only their light shows");
    intensity_ = knobs.addFloat("flames.intensity", 1.0, 0.0, 100.0, "flames",
                                "radiance of a flame sprite over its particle light's brightness");
    size_ = knobs.addFloat("flames.size", 1.0, 0.05, 10.0, "flames", "sprite size over its emitter's radius");
    softness_ = knobs.addFloat("flames.softness", 0.15, 0.0, 10.0, "flames",
                               "soft particles: a sprite fades out over this distance in front of a surface", "scene units");
}

std::string FlamesPass::skipReason(const KnobRegistry& knobs, const Scene& scene) const {
    if (!knobs.get(enabled_)) return "switched off (flames.enabled = false)";
    if (scene.flames.empty()) return "the scene has no flame particles";
    return {};
}

void FlamesPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "flames/flame.vert", .fragment = "flames/flame.frag"});
    params_.create();
    vao_ = gl::VertexArray::create();
}

std::vector<gpu::FlamesParams> FlamesPass::batches(const FrameContext& ctx) const {
    const FlameParticles& fire = ctx.scene.flames;
    const float scale = static_cast<float>(ctx.knobs.get(size_));
    const float gain = static_cast<float>(ctx.knobs.get(intensity_));
    std::vector<gpu::FlamesParams> out;
    for (size_t k = 0; k < fire.emitters.size(); ++k) {
        const FlameEmitter& e = fire.emitters[k];
        for (int j = 0; j < e.particles; ++j) {
            // The same particle as the light: flameParticles() numbers emitters from 1.
            const FlameParticle p = flameParticle(e, j, static_cast<std::uint32_t>(k) + 1U, ctx.frameIndex);
            if (out.empty() || out.back().count == gpu::FLAMES_BATCH) {
                out.emplace_back();
                out.back().count = 0;
                out.back().softness = static_cast<float>(ctx.knobs.get(softness_));
            }
            gpu::FlamesParams& b = out.back();
            const float brightness = std::max({p.intensity.r, p.intensity.g, p.intensity.b});
            const glm::dvec3 relative = glm::dvec3(p.position) - ctx.camera.origin;
            b.centre[b.count] = glm::vec4(glm::vec3(relative), e.radius * scale * (0.45f - 0.3f * p.age));
            b.emission[b.count] = glm::vec4(blackbodyColour(flameTemperature(p.age)) * (brightness * gain),
                                            e.radius * scale * (0.35f + 0.6f * p.age));
            ++b.count;
        }
    }
    return out;
}

void FlamesPass::execute(FrameContext& ctx) {
    gl::Framebuffer& fbo = target_.get(ctx, {"flames.result", "lbuffer"}, {}, "flames");
    fbo.clearColor(0, 0.0f, 0.0f, 0.0f, 0.0f);
    fbo.bind();
    const std::vector<gpu::FlamesParams> work = batches(ctx);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);  // emissive: added, in any order
    glDepthMask(GL_FALSE);
    ctx.texture("gbuffer.depth").bind(binding::GBUFFER_DEPTH_TEXTURE);
    program_->use();
    vao_.bind();
    int drawn = 0;
    for (const gpu::FlamesParams& b : work) {
        params_.upload(b, binding::PASS_UBO);
        glDrawArrays(GL_TRIANGLES, 0, 6 * b.count);
        drawn += b.count;
    }
    stats_ = std::to_string(drawn) + " flame sprites (each also a point light), " + std::to_string(work.size()) +
             (work.size() == 1 ? " draw" : " draws");
}

}  // namespace dw
