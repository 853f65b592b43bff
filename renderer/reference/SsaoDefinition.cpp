#include "renderer/reference/SsaoDefinition.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include "renderer/ao/SsaoMethod.h"
#include "renderer/reference/CameraRays.h"
#include "renderer/reference/MaterialEvaluator.h"
#include "renderer/reference/PixelRandom.h"
#include "renderer/reference/RayScene.h"
#include "renderer/reference/ReferenceModel.h"

namespace dw::reference {

namespace {

// A uniform unit vector from two uniform numbers.
glm::dvec3 unitVector(double u1, double u2) {
    const double z = 2.0 * u1 - 1.0, phi = 6.283185307179586 * u2, s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

// The first surface a camera ray through view point `q`'s projection meets, in view space.
bool surfaceThrough(const RayScene& rays, const CameraRays& camera, const glm::dvec3& q, glm::dvec3& s) {
    const glm::dvec2 ndc = camera.ndcOf(q);
    const glm::dvec3 dir = camera.directionAtNdc(ndc.x, ndc.y);
    const RayHit h = rays.intersect(glm::dvec3(0.0), dir, camera.nearPlane, camera.farPlane, Visibility::Camera);
    if (!h.hit) return false;
    const glm::uvec3 t = rays.triangle(h.instance, h.triangle);
    const auto& P = rays.instances()[h.instance].positions;
    s = camera.worldToView * ((1.0 - h.u - h.v) * P[t.x] + h.u * P[t.y] + h.v * P[t.z]);
    return true;
}

}  // namespace

SsaoDefinitionSettings SsaoDefinitionSettings::fromKnobs(const KnobRegistry& knobs, const Scene& scene) {
    SsaoDefinitionSettings s;
    const ReferenceModel m = ReferenceModel::fromKnobs(knobs, scene);
    s.radius = m.aoRadius;
    s.intensity = m.aoIntensity;
    auto number = [&](const char* name, double fallback) {
        const auto id = knobs.find(name);
        return id ? knobs.value(*id) : fallback;
    };
    s.kernelSize = static_cast<int>(number("ssao.samples", 16));
    s.bias = number("ssao.bias", 0.025);
    s.rangeCheck = number("ssao.range_check", 1) != 0.0;
    return s;
}

FloatImage ssaoDefinitionAo(const Scene& scene, const ReferenceRequest& request, const SsaoDefinitionSettings& settings,
                            ReferenceProgress* progress) {
    const int W = request.width, H = request.height;
    if (W < 1 || H < 1) throw Error("reference: the size must be at least 1x1");
    const RayScene rays(scene, glm::dvec3(request.camera.position));
    const CameraRays camera(request.camera, W, H);
    const std::vector<glm::vec4> kernel = SsaoMethod::kernel(settings.kernelSize);
    const double R = settings.radius, bias = settings.bias * R;
    FloatImage out;
    out.width = W;
    out.height = H;
    out.channels = 1;
    out.pixels.assign(static_cast<size_t>(W) * H, 1.0f);
    if (progress) {
        progress->totalPixels = static_cast<long long>(W) * H;
        progress->donePixels = 0;
    }
    tbb::task_arena arena(request.threads > 0 ? request.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
            for (int row = rows.begin(); row < rows.end(); ++row) {
                if (progress && progress->cancel.load(std::memory_order_relaxed)) return;
                for (int x = 0; x < W; ++x) {
                    const size_t p = static_cast<size_t>(row) * W + x;
                    const glm::dvec3 dir = camera.direction(x, row);
                    const RayHit hit = rays.intersect(glm::dvec3(0.0), dir, camera.nearPlane, camera.farPlane, Visibility::Camera);
                    if (!hit.hit) continue;
                    // The point and the shading normal the G-buffer would hold, exactly.
                    const SurfaceSample surface = evaluateSurface(scene, rays, hit, glm::dvec3(0.0), dir);
                    const glm::dvec3 P = camera.worldToView * surface.position;
                    const glm::dvec3 N = camera.worldToView * surface.normal;
                    double occlusion = 0.0;
                    long long count = 0;
                    for (int k = 0; k < settings.rotations; ++k) {
                        const std::uint64_t h = mix64(mix64(p * 977u + static_cast<std::uint64_t>(k)) ^ settings.seed);
                        const glm::dvec3 r = unitVector(unitFloat(h), unitFloat(mix64(h)));
                        for (const glm::vec4& kv : kernel) {
                            const glm::dvec3 kp(kv);
                            glm::dvec3 s = kp - 2.0 * glm::dot(r, kp) * r;  // GLSL reflect(kernel, r)
                            if (glm::dot(s, N) < 0.0) s = -s;
                            const glm::dvec3 Q = P + s * R;
                            ++count;
                            if (Q.z >= -camera.nearPlane) continue;  // behind the eye: off screen
                            const glm::dvec2 ndc = camera.ndcOf(Q);
                            if (ndc.x < -1.0 || ndc.x >= 1.0 || ndc.y < -1.0 || ndc.y >= 1.0) continue;
                            glm::dvec3 S;
                            if (!surfaceThrough(rays, camera, Q, S)) continue;
                            if (S.z < Q.z + bias) continue;  // the surface is behind the sample: not occluded
                            const double d = glm::length(S - P) / R;
                            double weight = 1.0 / (1.0 + d * d);
                            if (settings.rangeCheck) {
                                const double gap = std::abs(P.z - S.z);
                                weight *= gap <= R ? 1.0 : R / gap;
                            }
                            occlusion += weight;
                        }
                    }
                    out.pixels[p] = static_cast<float>(
                        std::clamp(1.0 - settings.intensity * occlusion / static_cast<double>(std::max<long long>(count, 1)), 0.0, 1.0));
                }
                if (progress) progress->donePixels += W;
            }
        });
    });
    if (progress && progress->cancel.load()) throw ReferenceCancelled();
    return out;
}

}  // namespace dw::reference
