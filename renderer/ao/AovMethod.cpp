#include "renderer/ao/AovMethod.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "renderer/gl/Texture.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Mesh.h"

namespace dw {

// The texture units of shaders/ao/aov_volume.frag, clear of the materials'
// (GpuScene::drawEach binds MATERIAL_BASE_COLOR_TEXTURE to
// MATERIAL_EMISSIVE_TEXTURE and MATERIAL_OCCLUSION_TEXTURE).
static_assert(binding::MATERIAL_OCCLUSION_TEXTURE < binding::AOV_VOLUME_DEPTH_TEXTURE &&
              binding::MATERIAL_EMISSIVE_TEXTURE < binding::AOV_VOLUME_DEPTH_TEXTURE);

AovMethod::AovMethod(KnobRegistry& knobs) {
    radius_ = knobs.addFloat("aov.radius", 1.0, 0.01, 20.0, "aov",
                             "AOV: how far a triangle's occlusion volume reaches (delta, world units; seed 000 "
                             "table 6.5: 1); larger volumes cover more pixels (overdraw)",
                             "units", true, true);
    radiusUnit_ = knobs.addEnum("aov.radius_unit", {"world", "scene_fraction"}, "world", "aov",
                                "world: aov.radius in world units (seed 000 and McGuire 2010; the AOV1-3 presets); "
                                "scene_fraction: in the scene's power-of-ten unit, as ssao.radius_unit (the same "
                                "volumes relative to a model whatever its scale)");
    falloff_ = knobs.addFloat("aov.falloff", 1.0, 0.0, 8.0, "aov",
                              "AOV: exponent k on the distance weight w^k, w the ray-traced AO's 1 / (1 + (d/R)^2) "
                              "averaged over the triangle's part within aov.radius (seed 000 table 6.5: 1, the "
                              "reference's weight; 0: every direction within the radius counts fully)");
    // In the order of the shift to the AO size: the choice's index is the shift.
    resolution_ = knobs.addEnum("aov.resolution", {"full", "half", "quarter"}, "half", "aov",
                                "AOV: accessibility buffer size, w x h, w/2 x h/2 or w/4 x h/4 (seed 000 table 6.5)", true);
}

std::string AovMethod::description() const {
    return "Ambient Occlusion Volumes (McGuire 2010; seed 000 4.6.4): each opaque triangle's volume adds its "
           "analytic form factor, with a falloff, at the G-buffer points it covers";
}

std::vector<std::string> AovMethod::knobNames() const {
    return {"aov.radius", "aov.radius_unit", "aov.falloff", "aov.resolution"};
}

float AovMethod::worldRadius(const KnobRegistry& knobs, const Bounds& bounds) const {
    const float r = knobs.get(radius_);
    return knobs.choice(radiusUnit_) == "world" ? r : r * static_cast<float>(sceneLengthUnit(bounds));
}

std::vector<OutputDecl> AovMethod::outputs() const {
    OutputDecl overdraw{"aov.overdraw", OutputKind::Count,
                        "AOV: volume fragments shaded per pixel of the accessibility buffer (R32UI; counted only when "
                        "looked at)",
                        texture2D(GL_R32UI), 1};
    overdraw.onDemand = true;
    return {
        {"aov.depth", OutputKind::Depth,
         "AOV: gbuffer.depth at the accessibility buffer's size (the volumes' depth test), stencil 1 on surfaces "
         "(DEPTH32F_STENCIL8)",
         texture2D(GL_DEPTH32F_STENCIL8), 1},
        {"aov.occlusion", OutputKind::Scalar,
         "AOV: summed occlusion of the volumes covering the pixel, before 1 - clamp (R32F, at the AO size)",
         texture2D(GL_R32F), 1},
        overdraw,
    };
}

ResourceDesc AovMethod::resource(const OutputDecl& output, const KnobRegistry& knobs) const {
    ResourceDesc d = output.resource;
    d.shift = knobs.get(resolution_);  // full, half, quarter: 0, 1, 2
    return d;
}

float AovMethod::insideMargin(const CameraUniforms& camera) {
    const float near = camera.clip.x, tanHalf = camera.clip.z, aspect = camera.clip.w;
    return near * std::sqrt(1.0f + tanHalf * tanHalf * (1.0f + aspect * aspect));
}

void AovMethod::setup(gl::ShaderLibrary& shaders) {
    volume_ = shaders.get({.vertex = "ao/aov_volume.vert", .fragment = "ao/aov_volume.frag",
                           .geometry = "ao/aov_volume.geom"});
    depthCopy_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "ao/aov_depth.frag"});
    resolve_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "ao/aov_resolve.frag"});
    params_.create();
}

void AovMethod::run(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const gl::Texture& raw = ctx.texture("ao.raw");
    const int w = raw.width(), h = raw.height();
    const bool countOverdraw = ctx.wants("aov.overdraw");
    gpu::AovParams p{};
    p.aoSize = {w, h};
    p.radius = worldRadius(k, ctx.gpu.bounds());
    p.falloff = k.get(falloff_);
    p.countOverdraw = countOverdraw ? 1 : 0;
    p.insideMargin = insideMargin(ctx.camera);
    params_.upload(p, binding::PASS_UBO);
    const DepthConvention depth = ctx.depth();
    glViewport(0, 0, w, h);

    // 1. gbuffer.depth at the AO size, for the volumes' depth test, and
    // stencil 1 where there is a surface: the sky's pixels (cleared to 0)
    // then shade no volume.
    depthTarget_.get(ctx, {}, "aov.depth", "AOV depth").bind();
    glClearBufferfi(GL_DEPTH_STENCIL, 0, depth.farDepth(), 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    ctx.texture("gbuffer.depth").bind(binding::AOV_GBUFFER_DEPTH_TEXTURE);
    depthCopy_->use();
    triangle_.draw();

    // 2. The volumes, their occlusion added up (depth read, not written).
    volumeTarget_.get(ctx, {"aov.occlusion"}, "aov.depth", "AOV volumes").bind();
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, zero);
    if (countOverdraw) {
        const gl::Texture& overdraw = ctx.texture("aov.overdraw");
        overdraw.clearUint(0u);
        overdraw.bindImage(binding::AOV_OVERDRAW_IMAGE, GL_READ_WRITE);
    }
    glDepthMask(GL_FALSE);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0);
    glEnable(GL_DEPTH_CLAMP);  // back faces past the far plane still count
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    ctx.texture("gbuffer.depth").bind(binding::AOV_VOLUME_DEPTH_TEXTURE);
    ctx.texture("gbuffer.normal").bind(binding::AOV_VOLUME_NORMAL_TEXTURE);
    volume_->use();
    std::size_t volumes = 0;
    for (int inside = 0; inside < 2; ++inside) {
        // Outside: front faces nearer than the surface; inside: back faces behind it.
        p.insidePass = inside;
        params_.upload(p, binding::PASS_UBO);
        glDepthFunc(inside ? depth.farther() : depth.nearer());
        ctx.gpu.drawEach(*volume_, GpuScene::Filter::Opaque, [&](std::size_t, const GpuScene::Draw& d) {
            const int flags = (d.mirrored ? gpu::AOV_DRAW_MIRRORED : 0) | (d.doubleSided ? gpu::AOV_DRAW_DOUBLE_SIDED : 0);
            volume_->set(2, flags);
            if (inside == 0) volumes += static_cast<std::size_t>(d.indexCount / 3) * (d.doubleSided ? 2 : 1);
            return true;
        });
    }
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glDepthMask(GL_TRUE);
    if (countOverdraw) glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);

    // 3. ao.raw = 1 - clamp(sum).
    rawTarget_.get(ctx, {"ao.raw"}, {}, "AOV accessibility").bind();
    ctx.texture("aov.occlusion").bind(binding::AOV_OCCLUSION_TEXTURE);
    resolve_->use();
    triangle_.draw();

    char line[200];
    std::snprintf(line, sizeof(line), "%zu volumes at %dx%d, radius %.3g, falloff %.3g", volumes, w, h, p.radius,
                  p.falloff);
    stats_ = line;
    if (countOverdraw) {
        // Read back only when counted (a stall): the mean and the most volume
        // fragments shaded per AO pixel, for bench's stats and --timings.
        const gl::Texture& overdraw = ctx.texture("aov.overdraw");
        std::vector<GLuint> counts(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        glGetTextureImage(overdraw.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                          static_cast<GLsizei>(counts.size() * sizeof(GLuint)), counts.data());
        double sum = 0.0;
        GLuint most = 0;
        for (GLuint c : counts) {
            sum += c;
            most = std::max(most, c);
        }
        std::snprintf(line, sizeof(line), ", overdraw mean %.2f max %u", sum / static_cast<double>(counts.size()), most);
        stats_ += line;
    }
}

}  // namespace dw
