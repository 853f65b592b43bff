#include "renderer/lighting/ShadowMaps.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/lighting/CasterCulling.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {

// Clip space (x, y in [-1, 1], depth already in [0, 1]: DepthConvention) to
// texture space (the seed's matrix B, without its depth remap).
const glm::mat4 kBias = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 0.0f)) *
                        glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 1.0f));

glm::vec3 anyUp(const glm::vec3& dir) { return std::fabs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0); }

struct Face {
    glm::vec3 dir, up;
};
// GL's cube face order and orientation (+X, -X, +Y, -Y, +Z, -Z).
const Face kFaces[6] = {{{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
                        {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}}};

}  // namespace

ShadowMaps::ShadowMaps(KnobRegistry& knobs) {
    enabled_ = knobs.addBool("shadows.enabled", true, "shadows", "shadow maps for lights whose 'shadow' flag is set");
    size_ = knobs.addInt("shadows.map_size", 1024, 64, 4096, "shadows",
                         "shadow map width and height (seed 002: 512 low, 1024 medium, 2048 high)", "px", true);
    pcf_ = knobs.addInt("shadows.pcf_radius", 1, 0, 3, "shadows",
                        "percentage-closer filtering over (2r + 1)^2 comparison taps", "texels", true);
    biasConstant_ = knobs.addFloat("shadows.bias_constant", 1.0, 0.0, 16.0, "shadows",
                                   "constant bias: the receiver moves this many shadow-map texels towards the light",
                                   "texels");
    biasSlope_ = knobs.addFloat("shadows.bias_slope", 2.5, 0.0, 32.0, "shadows",
                                "slope-scaled bias: depth offset in proportion to the surface's depth slope in the map "
                                "(glPolygonOffset factor)");
    pointMethod_ = knobs.addEnum("shadows.point_method", {"cube", "dual_paraboloid"}, 0, "shadows",
                                 "point lights: a cube map (6 renders) or two paraboloids (2 renders; Brabec 2002)", true);
    blendedCasters_ = knobs.addBool("shadows.blended_casters", false, "shadows",
                                    "blended (transparent) materials cast shadows as if they were opaque; off: they cast "
                                    "none (a shadow map holds one depth, not how much light a pane lets through)");
    reuse_ = knobs.addBool("shadows.reuse_map", true, "shadows",
                           "render each light's map just before shading it, reusing one map (seed 002 3.3); off: "
                           "keep one map per light, rendered before the lights are shaded");
    cullCasters_ = knobs.addBool("shadows.cull_casters", true, "shadows",
                                 "draw into each shadow map only the draws whose world-space box meets the map's volume "
                                 "(a directional map's fitted box, a spot's frustum, each cube face, each paraboloid half; "
                                 "never the side towards the light); the maps are identical either way");
    distance_ = knobs.addFloat("shadows.distance", 0.0, 0.0, 1e5, "shadows",
                               "how far from the camera a directional light's map reaches (0: as far as the scene reaches in view; "
                               "the map covers the scene's bounds intersected with the view either way)", "units");
}

void ShadowMaps::setup(gl::ShaderLibrary& shaders) {
    depth_ = shaders.get({.vertex = "shadow/depth.vert", .fragment = "shadow/depth.frag"});
    pointDistance_ = shaders.get({.vertex = "shadow/depth.vert", .fragment = "shadow/distance.frag"});
    paraboloid_ = shaders.get({.vertex = "shadow/paraboloid.vert", .fragment = "shadow/distance.frag", .defines = {"PARABOLOID"}});
    compare_ = gl::Sampler::createDepthCompare("shadow comparison");
    fbo_ = gl::Framebuffer::create("shadow map");
    fbo_.setNoColorBuffers();
    for (int k = 0; k < 3; ++k) ensure(static_cast<Kind>(k), 1, 1);
}

ShadowMaps::Kind ShadowMaps::kindOf(const Light& light, const KnobRegistry& knobs) const {
    // A spot light wider than kWideSpotDegrees would need a perspective map of
    // nearly 180 degrees (texels stretched without bound at its rim), so it
    // is shadowed like a point light.
    if (light.type == LightType::Directional) return Map2D;
    if (light.type == LightType::Spot && light.cutoffDegrees <= kWideSpotDegrees) return Map2D;
    return knobs.get(pointMethod_) == 0 ? Cube : Paraboloid;
}

void ShadowMaps::ensure(Kind kind, int layers, int size) {
    if (maps_[kind] && layers_[kind] == layers && maps_[kind].width() == size) return;
    const GLenum target = kind == Cube ? GL_TEXTURE_CUBE_MAP_ARRAY : GL_TEXTURE_2D_ARRAY;
    const int depth = kind == Cube ? 6 * layers : (kind == Paraboloid ? 2 * layers : layers);
    gl::MemoryOwner owner("shadow maps");
    maps_[kind] = gl::Texture::createArray(target, GL_DEPTH_COMPONENT32F, size, depth);
    maps_[kind].setLabel(kind == Map2D ? "shadow.maps" : (kind == Cube ? "shadow.cubes" : "shadow.paraboloids"));
    layers_[kind] = layers;
}

void ShadowMaps::beginFrame(const FrameContext& ctx, const int counts[3], bool reuse) {
    const int size = ctx.knobs.get(size_);
    mapSize_ = size;
    depthConvention_ = ctx.depth();
    // Lit where the receiver is no farther than the map (GL_LEQUAL, or
    // GL_GEQUAL reversed); outside the map the border reads as the far plane.
    glSamplerParameteri(compare_.id(), GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(depthConvention_.nearerOrEqual()));
    const float farDepth = depthConvention_.farDepth();
    const float border[4] = {farDepth, farDepth, farDepth, farDepth};
    glSamplerParameterfv(compare_.id(), GL_TEXTURE_BORDER_COLOR, border);
    bytesInUse_ = bytesKeepingAll_ = 0;
    rendered_ = 0;
    casters_ = {};
    const std::size_t texel = 4;  // DEPTH_COMPONENT32F
    for (int k = 0; k < 3; ++k) {
        const std::size_t perMap = static_cast<std::size_t>(size) * size * texel * (k == Cube ? 6 : (k == Paraboloid ? 2 : 1));
        bytesKeepingAll_ += perMap * counts[k];
        const int layers = counts[k] == 0 ? 0 : (reuse ? 1 : counts[k]);
        bytesInUse_ += perMap * layers;
        if (layers > 0) ensure(static_cast<Kind>(k), layers, size);
    }
}

float ShadowMaps::farDistance(const FrameContext& ctx, const Light& light, double radius) const {
    const Bounds& bounds = ctx.gpu.bounds();
    const float sceneRadius = bounds.radius() > 0.0f ? bounds.radius() : 1.0f;
    // The depth range: out to the light's radius, but no further than the
    // farthest corner of the scene (a bright light's radius can be far larger
    // than the scene, and the near plane scales with the far one). No
    // absolute floor, so a scene at any scale keeps its shadows.
    float far = std::isfinite(radius) && radius > 0 ? static_cast<float>(radius) : std::numeric_limits<float>::max();
    if (!bounds.empty()) {
        float farthest = 0.0f;
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner((c & 1) ? bounds.max.x : bounds.min.x, (c & 2) ? bounds.max.y : bounds.min.y,
                                   (c & 4) ? bounds.max.z : bounds.min.z);
            farthest = std::max(farthest, glm::length(corner - light.position));
        }
        far = std::min(far, farthest * 1.01f);
    }
    if (!std::isfinite(far) || far > 1e30f) far = glm::length(light.position) + sceneRadius;
    return std::max(far, sceneRadius * 1e-3f);
}

ShadowMaps::MapFit ShadowMaps::fitDirectional(const FrameContext& ctx, const Light& light) const {
    // Fit an orthographic box around the part of the view frustum in reach,
    // extended towards the light over the whole scene. Across the light, the
    // box is a constant size while the camera moves (so snapping it to whole
    // texels stops the edges shimmering): per axis either the scene's extent,
    // or the diameter of a sphere around the frustum slice, whichever is
    // smaller. The slice is the view intersected with the scene's bounds (and
    // shadows.distance): a view with near 0.05 and far 1e6 over a 20-unit
    // scene gets a map of the scene, not of a million units of empty frustum
    // (whose depth range left a float map too coarse for any bias: acne).
    const KnobRegistry& k = ctx.knobs;
    const Bounds& bounds = ctx.gpu.bounds();
    const float sceneRadius = bounds.radius() > 0.0f ? bounds.radius() : 1.0f;
    float nearC = ctx.camera.clip.x;
    float farC = k.get(distance_) > 0.0f ? std::min(k.get(distance_), ctx.camera.clip.y) : ctx.camera.clip.y;
    if (!bounds.empty()) {
        const glm::dmat4 worldToView = ctx.camera.worldToView();
        double zMin = 1e300, zMax = -1e300;  // distances ahead of the camera
        for (int c = 0; c < 8; ++c) {
            const double z = -(worldToView * glm::dvec4((c & 1) ? bounds.max.x : bounds.min.x,
                                                         (c & 2) ? bounds.max.y : bounds.min.y,
                                                         (c & 4) ? bounds.max.z : bounds.min.z, 1.0)).z;
            zMin = std::min(zMin, z);
            zMax = std::max(zMax, z);
        }
        if (zMax > nearC) {
            farC = std::min(farC, static_cast<float>(zMax));
            nearC = std::max(nearC, static_cast<float>(zMin));
        }
        farC = std::max(farC, nearC * 1.001f + sceneRadius * 1e-6f);
    }
    MapFit fit;
    const glm::dvec3 dir = glm::normalize(glm::dvec3(light.direction));
    const glm::dvec3 center = bounds.empty() ? glm::dvec3(0.0) : glm::dvec3(bounds.center());
    fit.eye = center - dir * (static_cast<double>(sceneRadius) * 2.0);
    fit.lightView = glm::lookAt(fit.eye, center, glm::dvec3(anyUp(glm::vec3(dir))));
    const glm::dmat4 viewToLight = fit.lightView * glm::inverse(ctx.camera.worldToView());
    const float t = ctx.camera.clip.z, a = ctx.camera.clip.w;
    const float zMid = 0.5f * (nearC + farC);
    float sphereR = 0.0f;
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (float z : {nearC, farC})
        for (float sx : {-1.0f, 1.0f})
            for (float sy : {-1.0f, 1.0f}) {
                const glm::vec4 pv(sx * z * t * a, sy * z * t, -z, 1.0f);
                sphereR = std::max(sphereR, glm::length(glm::vec3(pv) - glm::vec3(0.0f, 0.0f, -zMid)));
                const glm::vec3 pl(viewToLight * glm::dvec4(pv));
                lo = glm::min(lo, pl);
                hi = glm::max(hi, pl);
            }
    const glm::vec3 sphereC(viewToLight * glm::dvec4(0.0, 0.0, -zMid, 1.0));
    fitDirectionalBox(ctx, fit, glm::vec2(sphereC), sphereR, lo, hi);
    return fit;
}

void ShadowMaps::fitDirectionalBox(const FrameContext& ctx, MapFit& fit, const glm::vec2& sphereC, float sphereR,
                                   glm::vec3 lo, glm::vec3 hi) const {
    const Bounds& bounds = ctx.gpu.bounds();
    const float sceneRadius = bounds.radius() > 0.0f ? bounds.radius() : 1.0f;
    const int size = mapSize_;
    float extent = 2.0f * sphereR;
    glm::vec2 lo2 = sphereC - sphereR, hi2 = sphereC + sphereR;
    if (!bounds.empty()) {
        Bounds lb;  // the scene's box in light space (corners in double precision)
        for (int c = 0; c < 8; ++c)
            lb.add(glm::vec3(fit.lightView * glm::dvec4((c & 1) ? bounds.max.x : bounds.min.x,
                                                        (c & 2) ? bounds.max.y : bounds.min.y,
                                                        (c & 4) ? bounds.max.z : bounds.min.z, 1.0)));
        const float sceneExtent = std::max(lb.max.x - lb.min.x, lb.max.y - lb.min.y);
        if (sceneExtent <= extent) {
            // The whole scene, in a square box centred on it.
            extent = std::max(sceneExtent, sceneRadius * 1e-3f);
            const glm::vec2 c = 0.5f * (glm::vec2(lb.min) + glm::vec2(lb.max));
            lo2 = c - 0.5f * extent;
            hi2 = c + 0.5f * extent;
        }
        // Deep enough for every caster between the light and the view, and
        // no deeper: every caster and receiver is in the scene.
        lo.z = lb.min.z;
        hi.z = lb.max.z;
    }
    // Snap the box to whole texels of its (constant) size.
    const float texel = extent / static_cast<float>(size);
    lo2 = glm::floor(lo2 / texel) * texel;
    hi2 = lo2 + extent + texel;  // one texel of slack for the snap
    lo = glm::vec3(lo2, lo.z);
    hi = glm::vec3(hi2, hi.z);
    // 1e-3 as before for scenes 20 or more across, in proportion below.
    const float pad = std::min(1e-3f, sceneRadius * 1e-4f);
    fit.proj = depthConvention_.orthographic(lo.x, hi.x, lo.y, hi.y, -hi.z - pad, -lo.z + pad);
    fit.range.z = ctx.knobs.get(biasConstant_) * std::max(hi.x - lo.x, hi.y - lo.y) / static_cast<float>(size);
}

ShadowMaps::MapFit ShadowMaps::fitSpot(const FrameContext& ctx, const Light& light, float near, float far) const {
    MapFit fit;
    const float fov = 2.0f * light.cutoffDegrees + 2.0f;  // <= 2 * kWideSpotDegrees + 2
    const glm::dvec3 dir = glm::normalize(glm::dvec3(light.direction));
    fit.eye = glm::dvec3(light.position);
    fit.proj = depthConvention_.perspective(glm::radians(static_cast<double>(fov)), 1.0, near, far);
    fit.lightView = glm::lookAt(fit.eye, fit.eye + dir, glm::dvec3(anyUp(glm::vec3(dir))));
    fit.range.w = ctx.knobs.get(biasConstant_) * 2.0f * std::tan(glm::radians(fov * 0.5f)) / static_cast<float>(mapSize_);
    return fit;
}

std::vector<std::size_t> ShadowMaps::cullCasters(const FrameContext& ctx, const CasterVolume& volume) {
    // Blended surfaces cast no shadow unless shadows.blended_casters (then
    // as if opaque: a shadow map holds one depth, not a transmittance).
    const GpuScene::Filter filter = ctx.knobs.get(blendedCasters_) ? GpuScene::Filter::All : GpuScene::Filter::Opaque;
    const bool cull = ctx.knobs.get(cullCasters_);
    const std::vector<GpuScene::Draw>& draws = ctx.gpu.draws();
    std::vector<std::size_t> kept;
    kept.reserve(draws.size());
    for (std::size_t i = 0; i < draws.size(); ++i) {
        const GpuScene::Draw& d = draws[i];
        if (!GpuScene::matches(d, filter)) continue;
        const std::size_t triangles = static_cast<std::size_t>(d.indexCount) / 3;
        ++casters_.total;
        casters_.trianglesTotal += triangles;
        if (cull && !volume.mayCast(d.bounds)) continue;
        kept.push_back(i);
        ++casters_.drawn;
        casters_.trianglesDrawn += triangles;
    }
    return kept;
}

void ShadowMaps::drawCasters(const FrameContext& ctx, const gl::Program& program, const CasterVolume& volume) {
    ctx.gpu.drawDepthOnly(program, cullCasters(ctx, volume));
}

void ShadowMaps::target(Kind kind, int layer) {
    fbo_.attachDepthLayer(maps_[kind], 0, layer);
    fbo_.clearDepth(depthConvention_.farDepth());
}

void ShadowMaps::render2D(const FrameContext& ctx, const Light& light, float near, float far, int slot, ShadowLookup& out) {
    const MapFit fit = light.type == LightType::Directional ? fitDirectional(ctx, light) : fitSpot(ctx, light, near, far);
    out.range = fit.range;
    target(Map2D, slot);
    depth_->use();
    // Drawn relative to the light's eye: the light view less its translation.
    ctx.gpu.setDrawOrigin(fit.eye);
    depth_->set(2, glm::mat4(fit.proj * glm::translate(fit.lightView, fit.eye)));
    depth_->set(3, glm::vec3(0.0f));
    // The clip volume less its plane on the light's side: a directional
    // map's depth range reaches over the whole scene towards the light.
    drawCasters(ctx, *depth_, CasterVolume::frustum(fit.proj * fit.lightView, depthConvention_.reversed()));
    out.matrix = kBias * glm::mat4(fit.proj * fit.lightView * glm::inverse(ctx.camera.worldToView()));
}

void ShadowMaps::renderCube(const FrameContext& ctx, const Light& light, float near, float far, int slot, ShadowLookup& out) {
    // Each face stores the linear distance from the light (distance.frag,
    // which also applies the slope bias), not its own perspective depth.
    const DepthConvention& dc = depthConvention_;
    const glm::dmat4 projD = dc.perspective(glm::radians(90.0), 1.0, near, far);
    const glm::mat4 proj(projD);
    glDisable(GL_POLYGON_OFFSET_FILL);
    pointDistance_->use();
    const glm::dvec3 lightPos(light.position);
    ctx.gpu.setDrawOrigin(lightPos);  // positions relative to the light
    pointDistance_->set(3, glm::vec3(0.0f));
    pointDistance_->set(4, glm::vec4(near, far, ctx.knobs.get(biasSlope_), dc.reversed() ? 1.0f : 0.0f));
    for (int f = 0; f < 6; ++f) {
        target(Cube, 6 * slot + f);
        pointDistance_->set(2, proj * glm::lookAt(glm::vec3(0.0f), kFaces[f].dir, kFaces[f].up));
        const glm::dmat4 faceView =
            glm::lookAt(lightPos, lightPos + glm::dvec3(kFaces[f].dir), glm::dvec3(kFaces[f].up));
        drawCasters(ctx, *pointDistance_, CasterVolume::frustum(projD * faceView, dc.reversed()));
    }
    // World-aligned offset from the light, which is how cube maps are indexed.
    out.matrix = glm::mat4(glm::translate(glm::dmat4(1.0), -lightPos) * glm::inverse(ctx.camera.worldToView()));
    out.range = glm::vec4(near, far, 0.0f, ctx.knobs.get(biasConstant_) * 2.0f / static_cast<float>(mapSize_));
}

void ShadowMaps::renderParaboloid(const FrameContext& ctx, const Light& light, float near, float far, int slot,
                                  ShadowLookup& out) {
    const DepthConvention& dc = depthConvention_;
    const glm::vec3 axis = glm::normalize(light.direction);
    const glm::dvec3 lightPos(light.position);
    // Rotation only: drawn relative to the light (the draw origin).
    const glm::mat4 lightView = glm::lookAt(glm::vec3(0.0f), -axis, anyUp(axis));
    ctx.gpu.setDrawOrigin(lightPos);
    glEnable(GL_CLIP_DISTANCE0);
    glDisable(GL_POLYGON_OFFSET_FILL);  // distance.frag applies the slope bias
    paraboloid_->use();
    paraboloid_->set(2, lightView);
    paraboloid_->set(4, glm::vec4(near, far, ctx.knobs.get(biasSlope_), dc.reversed() ? 1.0f : 0.0f));
    paraboloid_->set(5, static_cast<float>(mapSize_));
    for (int h = 0; h < 2; ++h) {
        target(Paraboloid, 2 * slot + h);
        const float sign = h == 0 ? 1.0f : -1.0f;
        paraboloid_->set(3, glm::vec4(near, far, sign, dc.reversed() ? 1.0f : 0.0f));
        // The half the clip distance keeps, out to the far distance (depth 1).
        drawCasters(ctx, *paraboloid_, CasterVolume::hemisphere(lightPos, glm::dvec3(axis) * double(sign), far));
    }
    glDisable(GL_CLIP_DISTANCE0);
    out.matrix = glm::mat4(glm::dmat4(lightView) * glm::translate(glm::dmat4(1.0), -lightPos) *
                           glm::inverse(ctx.camera.worldToView()));
    // A paraboloid texel spans at most about 4 / size radians (at its rim).
    out.range = glm::vec4(near, far, 0.0f, ctx.knobs.get(biasConstant_) * 4.0f / static_cast<float>(mapSize_));
}

ShadowLookup ShadowMaps::render(const FrameContext& ctx, const Light& light, double radius, int slot) {
    const KnobRegistry& k = ctx.knobs;
    const Kind kind = kindOf(light, k);
    ShadowLookup out;
    out.params = glm::vec4(static_cast<float>(kind == Map2D ? 1 : (kind == Cube ? 2 : 3)), static_cast<float>(k.get(pcf_)),
                           1.0f / static_cast<float>(mapSize_), static_cast<float>(slot));
    // Camera-relative rendering (CameraUniforms::origin): the lookups map the
    // camera's view space to the light's space through absolute world space
    // in double precision, and each map is drawn relative to its light (the
    // draw origin), so a scene far from the world origin keeps its shadows.
    // Every length is relative to the scene's size, as the camera rule is:
    // absolute floors (1e-3 units) sized a directional map of a scene 1e-8
    // across 100 000 times too large, and its shadows were gone.
    const float far = farDistance(ctx, light, radius);
    const float near = far * 1e-3f;

    gl::resetPipelineState(mapSize_, mapSize_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depthConvention_.nearer());
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(depthConvention_.awaySign() * k.get(biasSlope_), 0.0f);
    fbo_.bind();
    if (kind == Map2D) render2D(ctx, light, near, far, slot, out);
    else if (kind == Cube) renderCube(ctx, light, near, far, slot, out);
    else renderParaboloid(ctx, light, near, far, slot, out);
    ctx.gpu.setDrawOrigin(ctx.camera.origin);  // back to camera-relative for the passes that follow
    ++rendered_;
    return out;
}

void ShadowMaps::bind() const {
    maps_[Map2D].bind(binding::SHADOW_2D_TEXTURE);
    maps_[Cube].bind(binding::SHADOW_CUBE_TEXTURE);
    maps_[Paraboloid].bind(binding::SHADOW_PARABOLOID_TEXTURE);
    for (GLuint unit : {binding::SHADOW_2D_TEXTURE, binding::SHADOW_CUBE_TEXTURE, binding::SHADOW_PARABOLOID_TEXTURE})
        compare_.bind(static_cast<int>(unit));
}

}  // namespace dw
