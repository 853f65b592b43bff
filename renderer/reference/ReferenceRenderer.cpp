#include "renderer/reference/ReferenceRenderer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <mutex>

#include "renderer/lighting/LightVolume.h"
#include "renderer/reference/CameraRays.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/reference/MaterialEvaluator.h"
#include "renderer/reference/PixelRandom.h"
#include "renderer/reference/RayScene.h"
#include "renderer/reference/ShadingReference.h"
#include "renderer/reference/SkyReference.h"
#include "renderer/reference/ToneMapReference.h"

namespace dw::reference {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kTile = 16;
// Blended surfaces composited along one primary ray at most (beyond them the
// ray goes on as if they were opaque). The glass scene's deepest pixel holds far fewer.
constexpr int kMaxBlendedLayers = 256;

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

double radicalInverse2(std::uint32_t i) {
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
    i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
    i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
    return static_cast<double>(i) * (1.0 / 4294967296.0);
}

// The i-th of n cosine-weighted directions about +Z (Malley's method over a
// Hammersley set rotated by (o1, o2)).
glm::dvec3 cosineDirection(int i, int n, double o1, double o2) {
    double u1 = (i + 0.5) / n + o1, u2 = radicalInverse2(static_cast<std::uint32_t>(i)) + o2;
    u1 -= std::floor(u1);
    u2 -= std::floor(u2);
    const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

// An orthonormal basis with `n` as its third axis (Duff et al. 2017).
void basis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
}

// Ray origins leave the surface by this much (Embree's triangles and hit
// distances are single precision, relative to the coordinates' size).
double offsetAt(const glm::dvec3& p, double sceneRadius) {
    const double m = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return 1e-5 * (m + 1e-3 * sceneRadius);
}

struct LightInView {
    const Light* light;
    glm::dvec3 worldPosition;  // origin-relative
    glm::dvec3 viewPosition, viewDirection;
    double radius;  // <= 0: unbounded
};

std::vector<LightInView> lightsInView(const Scene& scene, const ReferenceModel& model,
                                      const glm::dvec3& eye, const glm::dmat3& worldToView) {
    std::vector<LightInView> out;
    for (const Light& l : scene.lights) {
        if (!l.enabled) continue;
        double radius = -1.0;
        if (model.attenuation == AttenuationModel::Windowed && l.type != LightType::Directional) {
            const LightVolume v = computeLightVolume(l, model.threshold);
            if (v.shape == VolumeShape::Culled) continue;  // the window closes before it starts
            radius = std::isfinite(v.radius) ? v.radius : -1.0;
        }
        LightInView li;
        li.light = &l;
        li.worldPosition = glm::dvec3(l.position) - eye;
        li.viewPosition = worldToView * li.worldPosition;
        li.viewDirection = worldToView * glm::dvec3(l.direction);
        li.radius = radius;
        out.push_back(li);
    }
    return out;
}

FloatImage makeImage(int w, int h, int channels, float fill) {
    FloatImage img;
    img.width = w;
    img.height = h;
    img.channels = channels;
    img.pixels.assign(static_cast<size_t>(w) * h * channels, fill);
    return img;
}

template <typename Body>
void forEachTile(int width, int height, int threads, ReferenceProgress* progress,
                 const Body& body) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range2d<int>(0, height, kTile, 0, width, kTile),
            [&](const tbb::blocked_range2d<int>& r) {
                if (progress && progress->cancel.load(std::memory_order_relaxed)) return;
                body(r);
                if (progress)
                    progress->donePixels.fetch_add(static_cast<long long>(r.rows().size()) *
                                                   static_cast<long long>(r.cols().size()));
            });
    });
}

}  // namespace

int availableThreads() { return tbb::this_task_arena::max_concurrency(); }

const std::vector<std::string>& referenceBuffers() {
    static const std::vector<std::string> names = {"lbuffer", "final", "ao", "shadow"};
    return names;
}

const FloatImage* ReferenceImages::buffer(const std::string& name) const {
    if (name == "lbuffer") return &lbuffer;
    if (name == "final") return &final;
    if (name == "ao") return &ao;
    if (name == "shadow") return &shadow;
    return nullptr;
}

ReferenceImages renderReference(const Scene& scene, const ReferenceModel& model,
                                const ReferenceRequest& request, ReferenceProgress* progress) {
    const int W = request.width, H = request.height;
    if (W < 1 || H < 1) throw Error("reference: the size must be at least 1x1");
    if (model.rayTracedAo && model.aoRays < 1)
        throw Error("reference: AO needs at least 1 ray per pixel");
    const auto buildStart = Clock::now();
    const glm::dvec3 eye(request.camera.position);
    const RayScene rays(scene, eye, model.blendedCasters);
    ReferenceImages out;
    out.stats.buildSeconds = secondsSince(buildStart);
    out.stats.triangles = rays.triangleCount();
    out.stats.threads =
        request.threads > 0 ? request.threads : tbb::this_task_arena::max_concurrency();

    const CameraRays camera(request.camera, W, H);
    const std::vector<LightInView> lights = lightsInView(scene, model, eye, camera.worldToView);
    const SkyReference sky(scene, model);
    const glm::dvec3 ambient(scene.ambient);
    const double aoRadius = model.aoRadius;

    out.lbuffer = makeImage(W, H, 4, 1.0f);
    out.ao = makeImage(W, H, 1, 1.0f);
    out.shadow = makeImage(W, H, 1, 1.0f);
    out.background.assign(static_cast<size_t>(W) * H, 0);
    std::vector<double> aoError(static_cast<size_t>(W) * H, -1.0);
    std::atomic<long long> shadowRays{0}, aoRays{0}, blendedHits{0};
    if (progress) {
        progress->totalPixels = static_cast<long long>(W) * H;
        progress->donePixels = 0;
    }

    const auto start = Clock::now();
    forEachTile(W, H, request.threads, progress, [&](const tbb::blocked_range2d<int>& r) {
        long long localShadow = 0, localAo = 0, localLayers = 0;
        // One surface's radiance towards the eye. An opaque one (`transparent`
        // false) writes the pixel's AO and shadow; a blended one gets no AO
        // (it is not in the G-buffer SSAO reads) but receives shadows.
        auto shadeSurface = [&](const SurfaceSample& surface, bool transparent, size_t p) {
            glm::dvec3 radiance;
            const SurfaceSample& s = surface;
            const double eps = offsetAt(s.position, rays.sceneRadius());
            const glm::dvec3 origin = s.position + s.geometricNormal * eps;
            SurfacePoint sp;
            sp.position = camera.worldToView * s.position;
            sp.normal = camera.worldToView * s.normal;
            sp.diffuse = s.diffuse;
            sp.specular = s.specular;
            sp.exponent = s.exponent;

            // Ambient accessibility by rays.
            double access = 1.0;
            if (model.rayTracedAo && !transparent) {
                glm::dvec3 t, b;
                basis(s.normal, t, b);
                const std::uint64_t h =
                    mix64(mix64(p) ^ (static_cast<std::uint64_t>(model.seed) << 32));
                const double o1 = unitFloat(h), o2 = unitFloat(mix64(h));
                const int n = model.aoRays;
                double sum = 0.0, sumSq = 0.0;
                for (int i = 0; i < n; ++i) {
                    const glm::dvec3 l = cosineDirection(i, n, o1, o2);
                    const glm::dvec3 w = t * l.x + b * l.y + s.normal * l.z;
                    double weight = 0.0;
                    if (glm::dot(w, s.geometricNormal) <= 0.0) {
                        weight = 1.0;  // into the surface itself: occluded at distance 0
                    } else {
                        ++localAo;
                        const RayHit o =
                            rays.intersect(origin, w, 0.0, aoRadius, Visibility::Secondary);
                        if (o.hit) {
                            const glm::uvec3 tri = rays.triangle(o.instance, o.triangle);
                            const auto& P = rays.instances()[o.instance].positions;
                            const glm::dvec3 q =
                                (1.0 - o.u - o.v) * P[tri.x] + o.u * P[tri.y] + o.v * P[tri.z];
                            const double d = glm::length(q - s.position) / aoRadius;
                            weight = 1.0 / (1.0 + d * d);
                        }
                    }
                    sum += weight;
                    sumSq += weight * weight;
                }
                const double mean = sum / n;
                const double variance =
                    n > 1 ? std::max(sumSq / n - mean * mean, 0.0) * n / (n - 1) : 0.0;
                access = std::clamp(1.0 - model.aoIntensity * mean, 0.0, 1.0);
                aoError[p] = model.aoIntensity * std::sqrt(variance / n);
            }
            if (!transparent) out.ao.pixels[p] = static_cast<float>(access);
            // The GPU's transparent fragments take no baked occlusion either
            // (shaders/oit/transparent.frag).
            if (model.bakedOcclusion && !transparent) access *= s.occlusion;
            const glm::dvec3 reflectance =
                s.diffuse + (model.ambientSpecular ? s.specular : glm::dvec3(0.0));
            radiance = ambient * reflectance * access + s.emissive;

            double lit = 0.0, unshadowed = 0.0;
            for (const LightInView& li : lights) {
                const glm::dvec3 c =
                    shadeLight(*li.light, li.viewPosition, li.viewDirection, li.radius, sp,
                               model.attenuation, model.windowExponent);
                if (c == glm::dvec3(0.0)) continue;
                if (model.shadows && li.light->castShadows) {
                    bool blocked;
                    ++localShadow;
                    if (li.light->type == LightType::Directional) {
                        blocked =
                            rays.occluded(origin, -glm::normalize(glm::dvec3(li.light->direction)),
                                          0.0, std::numeric_limits<double>::infinity());
                    } else {
                        // Up to the light, short of it by the offset.
                        const glm::dvec3 toLight = li.worldPosition - origin;
                        const double d = glm::length(toLight);
                        blocked = d > eps && rays.occluded(origin, toLight / d, 0.0, d - eps);
                    }
                    const double y = luminance(c.r, c.g, c.b);
                    unshadowed += y;
                    if (blocked) continue;
                    lit += y;
                }
                radiance += c;
            }
            if (unshadowed > 0.0 && !transparent)
                out.shadow.pixels[p] = static_cast<float>(lit / unshadowed);
            return radiance;
        };
        for (int row = r.rows().begin(); row < r.rows().end(); ++row) {
            for (int x = r.cols().begin(); x < r.cols().end(); ++x) {
                const size_t p = static_cast<size_t>(row) * W + x;
                const glm::dvec3 dir = camera.direction(x, row);
                // Front to back: blended surfaces composited over what lies
                // behind them ("over" with premultiplied alpha, in exact depth
                // order), until an opaque surface or the sky.
                glm::dvec3 radiance(0.0);
                double transmittance = 1.0;
                double tNear = camera.nearPlane;
                for (int layer = 0;; ++layer) {
                    const RayHit hit = rays.intersect(glm::dvec3(0.0), dir, tNear, camera.farPlane,
                                                      Visibility::Camera);
                    if (!hit.hit) {
                        radiance += transmittance * sky.radiance(glm::normalize(dir));
                        out.background[p] = 1;
                        break;
                    }
                    const SurfaceSample surface = evaluateSurface(rays, hit, glm::dvec3(0.0), dir);
                    if (rays.blended(hit.instance) && layer < kMaxBlendedLayers) {
                        radiance += transmittance * surface.alpha * shadeSurface(surface, true, p);
                        transmittance *= 1.0 - surface.alpha;
                        tNear = hit.t * (1.0 + 1e-6);
                        ++localLayers;
                        continue;
                    }
                    radiance += transmittance * shadeSurface(surface, false, p);
                    break;
                }
                for (int c = 0; c < 3; ++c)
                    out.lbuffer.pixels[p * 4 + c] = static_cast<float>(radiance[c]);
            }
        }
        shadowRays += localShadow;
        aoRays += localAo;
        blendedHits += localLayers;
    });
    if (progress && progress->cancel.load()) throw ReferenceCancelled();
    out.stats.blendedHits = blendedHits.load();
    out.stats.seconds = secondsSince(start);
    out.stats.primaryRays = static_cast<long long>(W) * H;
    out.stats.shadowRays = shadowRays.load();
    out.stats.aoRays = aoRays.load();
    double sumErr = 0.0;
    long long counted = 0;
    for (double e : aoError)
        if (e >= 0.0) {
            sumErr += e;
            out.stats.aoStandardErrorMax = std::max(out.stats.aoStandardErrorMax, e);
            ++counted;
        }
    out.stats.aoStandardErrorMean = counted > 0 ? sumErr / counted : 0.0;
    out.final = toneMap(out.lbuffer, out.background, model);
    return out;
}

RayThroughput measureRayThroughput(const Scene& scene, const ReferenceModel& model,
                                   const ReferenceRequest& request) {
    const int W = request.width, H = request.height;
    const glm::dvec3 eye(request.camera.position);
    const RayScene rays(scene, eye, model.blendedCasters);
    const CameraRays camera(request.camera, W, H);
    const std::vector<LightInView> lights = lightsInView(scene, model, eye, camera.worldToView);
    std::atomic<long long> total{0};
    const auto start = Clock::now();
    forEachTile(W, H, request.threads, nullptr, [&](const tbb::blocked_range2d<int>& r) {
        long long local = 0;
        for (int row = r.rows().begin(); row < r.rows().end(); ++row)
            for (int x = r.cols().begin(); x < r.cols().end(); ++x) {
                const glm::dvec3 dir = camera.direction(x, row);
                const RayHit hit = rays.intersect(glm::dvec3(0.0), dir, camera.nearPlane,
                                                  camera.farPlane, Visibility::Camera);
                ++local;
                if (!hit.hit) continue;
                const glm::uvec3 tri = rays.triangle(hit.instance, hit.triangle);
                const auto& P = rays.instances()[hit.instance].positions;
                const glm::dvec3 q =
                    (1.0 - hit.u - hit.v) * P[tri.x] + hit.u * P[tri.y] + hit.v * P[tri.z];
                glm::dvec3 ng =
                    glm::normalize(glm::cross(P[tri.y] - P[tri.x], P[tri.z] - P[tri.x]));
                if (glm::dot(ng, dir) > 0.0) ng = -ng;
                const glm::dvec3 origin = q + ng * offsetAt(q, rays.sceneRadius());
                if (model.shadows)
                    for (const LightInView& li : lights) {
                        if (!li.light->castShadows) continue;
                        const glm::dvec3 toLight = li.light->type == LightType::Directional
                                                       ? -glm::dvec3(li.light->direction) * 1e30
                                                       : li.worldPosition - origin;
                        const double d = glm::length(toLight);
                        (void)rays.occluded(origin, toLight / d, 0.0, d);
                        ++local;
                    }
                if (model.rayTracedAo) {
                    glm::dvec3 t, b;
                    basis(ng, t, b);
                    for (int i = 0; i < model.aoRays; ++i) {
                        const glm::dvec3 l = cosineDirection(i, model.aoRays, 0.25, 0.5);
                        (void)rays.intersect(origin, t * l.x + b * l.y + ng * l.z, 0.0,
                                             model.aoRadius, Visibility::Secondary);
                        ++local;
                    }
                }
            }
        total += local;
    });
    RayThroughput t;
    t.seconds = secondsSince(start);
    t.rays = total.load();
    return t;
}

}  // namespace dw::reference
