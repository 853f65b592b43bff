#include "renderer/passes/LightTablePass.h"
#include "renderer/gl/MemoryLedger.h"

#include "renderer/graph/ViewFrustum.h"

#include <array>
#include <cmath>

#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Scene.h"

namespace dw {

LightTablePass::LightTablePass(KnobRegistry& knobs) {
    threshold_ = knobs.addFloat("lighting.threshold", 1.0 / 255.0, 1e-5, 0.25, "lighting",
                                "intensity at which a light's volume ends: I_max * att(r) = threshold (seed 001 eq. 1); "
                                "larger means smaller volumes, less work, and light cut off sooner",
                                "", true, true);
    frustumCull_ = knobs.addBool("lighting.frustum_cull", true, "lighting",
                                 "skip light volumes entirely outside the view frustum (volume strategies)");
}

std::vector<OutputDecl> LightTablePass::outputs() const {
    // A buffer sized by the scene's light count, so the pass owns it (imported).
    OutputDecl d{"lights.table", OutputKind::Scalar,
                 "the light table: one 224-byte std430 row per light (volume, view-space position and radius, "
                 "direction and cutoff, intensity, attenuation, shadow lookup)",
                 imported(), 1};
    return {d};
}

void LightTablePass::setup(gl::ShaderLibrary&) {
    gl::MemoryOwner owner("light table");
    buffer_ = gl::Buffer::create(sizeof(LightGpu), nullptr, true, "lights.table");
}

void LightTablePass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const double threshold = k.get(threshold_);
    // Camera-relative: view-space values from world ones in double precision.
    const glm::dmat4 view = ctx.camera.worldToView();
    const ViewFrustum frustum(ctx.camera.worldToClip());
    const bool cull = k.get(frustumCull_);
    table_ = {};
    int perType[3] = {0, 0, 0}, outside = 0;
    for (const Light& l : ctx.scene.lights) {
        if (!l.enabled) continue;
        const LightVolume v = computeLightVolume(l, threshold);
        if (v.shape == VolumeShape::Culled) {
            ++table_.belowThreshold;
            continue;
        }
        LightGpu g;
        g.volume = ctx.camera.relative(v.transform);
        const glm::vec3 dirView = glm::normalize(glm::vec3(view * glm::dvec4(glm::dvec3(l.direction), 0.0)));
        g.positionRadius = glm::vec4(glm::vec3(view * glm::dvec4(glm::dvec3(l.position), 1.0)),
                                     std::isfinite(v.radius) ? static_cast<float>(v.radius) : 0.0f);
        g.directionCutoff = glm::vec4(dirView, std::cos(glm::radians(l.cutoffDegrees)));
        g.intensityExponent = glm::vec4(l.intensity, l.exponent);
        const int type = l.type == LightType::Directional ? gpu::LIGHT_DIRECTIONAL
                         : l.type == LightType::Point     ? gpu::LIGHT_POINT
                                                          : gpu::LIGHT_SPOT;
        const bool cone = l.type == LightType::Spot && l.falloff == SpotFalloff::InnerOuterCone;
        if (cone) g.intensityExponent.w = coneRampScale(l);
        g.attenuation = glm::vec4(l.attenuation.constant, l.attenuation.linear, l.attenuation.quadratic,
                                  static_cast<float>(cone ? kLightKindSpotCone : type));
        LightTableEntry e;
        e.row = static_cast<int>(table_.rows.size());
        e.light = &l;
        e.volume = v;
        const bool bounded = l.type != LightType::Directional && v.shape != VolumeShape::FullScreen;
        e.inFrustum = !(cull && bounded && frustum.sphereOutside(glm::dvec3(l.position), v.radius));
        outside += e.inFrustum ? 0 : 1;
        ++perType[type];
        table_.rows.push_back(g);
        table_.entries.push_back(e);
    }
    // An empty table still binds one (unused) row.
    const std::size_t bytes = std::max<std::size_t>(table_.rows.size(), 1) * sizeof(LightGpu);
    gl::MemoryOwner owner("light table");
    buffer_.ensureSize(bytes, "lights.table");
    if (!table_.rows.empty()) buffer_.update(0, table_.rows.size() * sizeof(LightGpu), table_.rows.data());
    table_.buffer = &buffer_;
    buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::LIGHT_SSBO);
    ctx.outputs.bindBuffer("lights.table", &buffer_, sizeof(LightGpu), std::max<std::size_t>(table_.rows.size(), 1));
    ctx.lightTable = &table_;
    stats_ = std::to_string(table_.rows.size()) + " lights: " + std::to_string(perType[0]) + " directional, " +
             std::to_string(perType[1]) + " point, " + std::to_string(perType[2]) + " spot; " + std::to_string(outside) +
             " outside the frustum, " + std::to_string(table_.belowThreshold) + " below threshold";
}

}  // namespace dw
