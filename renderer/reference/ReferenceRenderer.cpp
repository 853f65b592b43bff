#include "renderer/reference/ReferenceRenderer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <memory>
#include <mutex>

#include "renderer/lighting/LightVolume.h"
#include "renderer/reference/CameraRays.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/reference/MaterialEvaluator.h"
#include "renderer/reference/PixelRandom.h"
#include "renderer/reference/RayScene.h"
#include "renderer/reference/RaySceneCache.h"
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
// distances are single precision, relative to the coordinates' size): `p` in
// the ray scene's frame (what Embree holds), `fromEye` the same point
// relative to the camera. In a per-camera frame the two are equal.
double offsetAt(const glm::dvec3& p, const glm::dvec3& fromEye, double sceneRadius) {
    const double m = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), std::abs(fromEye.x), std::abs(fromEye.y),
                               std::abs(fromEye.z)});
    return 1e-5 * (m + 1e-3 * sceneRadius);
}

struct LightInView {
    const Light* light;
    glm::dvec3 worldPosition;  // relative to the ray scene's origin
    glm::dvec3 viewPosition, viewDirection;
    double radius;  // <= 0: unbounded
};

// `origin`: the ray scene's; `cameraPosition`: world space.
std::vector<LightInView> lightsInView(const Scene& scene, const ReferenceModel& model, const glm::dvec3& origin,
                                      const glm::dvec3& cameraPosition, const glm::dmat3& worldToView) {
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
        li.worldPosition = glm::dvec3(l.position) - origin;
        li.viewPosition = worldToView * (glm::dvec3(l.position) - cameraPosition);
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
    static const std::vector<std::string> names = {"lbuffer", "final", "ao", "shadow", "spp_error"};
    return names;
}

double meanRelativeSppError(const ReferenceImages& images) {
    const FloatImage& e = images.sppError;
    const FloatImage& l = images.lbuffer;
    if (e.pixels.empty() || l.pixels.size() != e.pixels.size() * 4) return 0.0;
    double sum = 0.0;
    for (size_t p = 0; p < e.pixels.size(); ++p)
        sum += e.pixels[p] / (luminance(l.pixels[p * 4], l.pixels[p * 4 + 1], l.pixels[p * 4 + 2]) + 1e-3);
    return sum / static_cast<double>(e.pixels.size());
}

std::string pixelSamplesVerdict(const ReferenceImages& images, const ReferenceModel& model) {
    constexpr double kHalfStep = kSppEnough;
    const double mean = meanRelativeSppError(images);
    const bool enough = mean < kHalfStep;
    // The standard error falls as 1/sqrt(N): the N that would bring it under, rounded up to a power of 4.
    int next = model.pixelSamples;
    while (!enough && next < 65536 && mean * std::sqrt(static_cast<double>(model.pixelSamples) / next) >= kHalfStep) next *= 4;
    const bool beyond = mean * std::sqrt(static_cast<double>(model.pixelSamples) / next) >= kHalfStep;
    // Below 16 samples the spread underestimates the error (the extrapolation is optimistic): "at least".
    std::string advice;
    if (!enough && beyond && model.pixelSamples >= 65536)
        advice = "; not enough even at the maximum, --spp 65536";
    else if (!enough && beyond)
        advice = "; more than the maximum --spp 65536 would be needed";
    else if (!enough)
        advice = std::string(model.pixelSamples < 16 ? "; at least about --spp " : "; about --spp ") +
                 std::to_string(next) + " would be enough";
    char text[320];
    std::snprintf(text, sizeof(text),
                  "pixel samples: %d (%s), relative standard error of the pixels' luminance: mean %.4g: %s (half an "
                  "8-bit step is %.4g)%s",
                  model.pixelSamples, pixelFilterName(model.pixelFilter), mean, enough ? "enough" : "not enough",
                  kHalfStep, advice.c_str());
    return text;
}

const FloatImage* ReferenceImages::buffer(const std::string& name) const {
    if (name == "lbuffer") return &lbuffer;
    if (name == "final") return &final;
    if (name == "ao") return &ao;
    if (name == "shadow") return &shadow;
    if (name == "spp_error") return &sppError;
    return nullptr;
}

namespace {

// What every pixel of one render reads.
struct Trace {
    const Scene& scene;
    const RayScene& rays;
    const ReferenceModel& model;
    const CameraRays& camera;
    glm::dvec3 eye;  // the camera's position relative to the ray scene's origin
    std::vector<LightInView> lights;
    SkyReference sky;
    glm::dvec3 ambient;
    const std::atomic<bool>* cancel = nullptr;  // set: a pixel stops between its samples (many samples a pixel)
};

// What the pixels write, and the rays a tile cast.
struct TraceOutput {
    ReferenceImages& images;
    std::vector<double>& aoError;  // per pixel; -1 where no AO was estimated
};
// What one sample of a pixel found: its radiance, and the opaque surface's
// accessibility, shadow factor and AO standard error (1, 1, -1 without one).
struct SampleOutput {
    double ao = 1.0, shadow = 1.0, aoError = -1.0;
    bool sky = false;
};
struct TileCounts {
    long long shadow = 0, ao = 0, layers = 0;
};

// The accessibility A at an opaque surface by the model's AO rays; writes
// the estimate's standard error to aoError[p].
double ambientAccess(const Trace& t, const SurfaceSample& s, const glm::dvec3& origin, std::uint64_t p, SampleOutput& out,
                     TileCounts& counts) {
    const ReferenceModel& model = t.model;
    glm::dvec3 tu, tb;
    basis(s.normal, tu, tb);
    const std::uint64_t h = mix64(mix64(p) ^ (static_cast<std::uint64_t>(model.seed) << 32));
    const double o1 = unitFloat(h), o2 = unitFloat(mix64(h));
    const int n = model.aoRays;
    double sum = 0.0, sumSq = 0.0;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 l = cosineDirection(i, n, o1, o2);
        const glm::dvec3 w = tu * l.x + tb * l.y + s.normal * l.z;
        double weight = 0.0;
        if (glm::dot(w, s.geometricNormal) <= 0.0) {
            weight = 1.0;  // into the surface itself: occluded at distance 0
        } else {
            ++counts.ao;
            const RayHit o = t.rays.intersect(origin, w, 0.0, model.aoRadius, Visibility::Secondary);
            if (o.hit) {
                const glm::uvec3 tri = t.rays.triangle(o.instance, o.triangle);
                const auto& P = t.rays.instances()[o.instance].positions;
                const glm::dvec3 q = (1.0 - o.u - o.v) * P[tri.x] + o.u * P[tri.y] + o.v * P[tri.z];
                const double d = glm::length(q - s.position) / model.aoRadius;
                weight = 1.0 / (1.0 + d * d);
            }
        }
        sum += weight;
        sumSq += weight * weight;
    }
    const double mean = sum / n;
    const double variance = n > 1 ? std::max(sumSq / n - mean * mean, 0.0) * n / (n - 1) : 0.0;
    out.aoError = model.aoIntensity * std::sqrt(variance / n);
    return std::clamp(1.0 - model.aoIntensity * mean, 0.0, 1.0);
}

// Adds every light's contribution at the surface to `radiance` (in the
// lights' order), shadow rays included; `lit` and `unshadowed` sum the
// shadow-casting lights' luminance with and without shadows.
void directLight(const Trace& t, const SurfacePoint& sp, const glm::dvec3& origin, double eps, TileCounts& counts,
                 glm::dvec3& radiance, double& lit, double& unshadowed) {
    const ReferenceModel& model = t.model;
    for (const LightInView& li : t.lights) {
        const glm::dvec3 c = shadeLight(*li.light, li.viewPosition, li.viewDirection, li.radius, sp, model.attenuation,
                                        model.windowExponent);
        if (c == glm::dvec3(0.0)) continue;
        if (model.shadows && li.light->castShadows) {
            bool blocked;
            ++counts.shadow;
            if (li.light->type == LightType::Directional) {
                blocked = t.rays.occluded(origin, -glm::normalize(glm::dvec3(li.light->direction)), 0.0,
                                          std::numeric_limits<double>::infinity(), model.blendedCasters);
            } else {
                // Up to the light, short of it by the offset.
                const glm::dvec3 toLight = li.worldPosition - origin;
                const double d = glm::length(toLight);
                blocked = d > eps && t.rays.occluded(origin, toLight / d, 0.0, d - eps, model.blendedCasters);
            }
            const double y = luminance(c.r, c.g, c.b);
            unshadowed += y;
            if (blocked) continue;
            lit += y;
        }
        radiance += c;
    }
}

// One surface's radiance towards the eye. An opaque one (`transparent`
// false) writes the pixel's AO and shadow; a blended one gets no AO (it is
// not in the G-buffer SSAO reads) but receives shadows.
glm::dvec3 shadeSurface(const Trace& t, const SurfaceSample& s, bool transparent, std::uint64_t p, SampleOutput& out,
                        TileCounts& counts) {
    const ReferenceModel& model = t.model;
    const glm::dvec3 fromEye = s.position - t.eye;
    const double eps = offsetAt(s.position, fromEye, t.rays.sceneRadius());
    const glm::dvec3 origin = s.position + s.geometricNormal * eps;
    SurfacePoint sp;
    sp.position = t.camera.worldToView * fromEye;
    sp.normal = t.camera.worldToView * s.normal;
    sp.diffuse = s.diffuse;
    sp.specular = s.specular;
    sp.exponent = s.exponent;

    double access = 1.0;
    if (model.rayTracedAo && !transparent) access = ambientAccess(t, s, origin, p, out, counts);
    if (!transparent) out.ao = access;
    // The GPU's transparent fragments take no baked occlusion either
    // (shaders/oit/transparent.frag).
    if (model.bakedOcclusion && !transparent) access *= s.occlusion;
    const glm::dvec3 reflectance = s.diffuse + (model.ambientSpecular ? s.specular : glm::dvec3(0.0));
    glm::dvec3 radiance = t.ambient * reflectance * access + s.emissive;

    double lit = 0.0, unshadowed = 0.0;
    directLight(t, sp, origin, eps, counts, radiance, lit, unshadowed);
    if (unshadowed > 0.0 && !transparent) out.shadow = lit / unshadowed;
    return radiance;
}

// One sample's radiance through the image point (x, row) + (fx, fy) (pixel
// units, row counted from the top, fy downwards): front to back, blended
// surfaces composited over what lies behind them ("over" with premultiplied
// alpha, in exact depth order), until an opaque surface or the sky. `p`
// seeds the sample's AO pattern (the pixel's index for its first sample).
glm::dvec3 traceSample(const Trace& t, int x, int row, double fx, double fy, std::uint64_t p, SampleOutput& out,
                       TileCounts& counts) {
    const glm::dvec3 dir = t.camera.directionAt(x + fx, row + fy);
    glm::dvec3 radiance(0.0);
    double transmittance = 1.0;
    double tNear = t.camera.nearPlane;
    for (int layer = 0;; ++layer) {
        const RayHit hit = t.rays.intersect(t.eye, dir, tNear, t.camera.farPlane, Visibility::Camera);
        if (!hit.hit) {
            radiance += transmittance * t.sky.radiance(glm::normalize(dir));
            out.sky = true;
            break;
        }
        const SurfaceSample surface = evaluateSurface(t.scene, t.rays, hit, t.eye, dir);
        if (t.rays.blended(hit.instance) && layer < kMaxBlendedLayers) {
            radiance += transmittance * surface.alpha * shadeSurface(t, surface, true, p, out, counts);
            transmittance *= 1.0 - surface.alpha;
            tNear = hit.t * (1.0 + 1e-6);
            ++counts.layers;
            continue;
        }
        radiance += transmittance * shadeSurface(t, surface, false, p, out, counts);
        break;
    }
    return radiance;
}

// A unit-interval sample mapped through the filter's inverse CDF, as an
// offset from the pixel's corner: box [0, 1); tent [-0.5, 1.5), peaked at 0.5.
double filterOffset(PixelFilter filter, double u) {
    if (filter == PixelFilter::Box) return u;
    const double d = u < 0.5 ? std::sqrt(2.0 * u) - 1.0 : 1.0 - std::sqrt(2.0 - 2.0 * u);
    return 0.5 + d;
}

// Sample i of the pixel's n: the pixel's centre for one sample; else the
// i-th Hammersley point shifted by the pixel's own rotation (seeded).
glm::dvec2 pixelOffset(const Trace& t, size_t p, int i, int n) {
    if (n == 1) return {0.5, 0.5};
    const std::uint64_t h = mix64(mix64(p ^ 0x5bd1e995ull) ^ (static_cast<std::uint64_t>(t.model.seed) << 32));
    double u = (i + 0.5) / n + unitFloat(h), v = radicalInverse2(static_cast<std::uint32_t>(i)) + unitFloat(mix64(h));
    u -= std::floor(u);
    v -= std::floor(v);
    return {filterOffset(t.model.pixelFilter, u), filterOffset(t.model.pixelFilter, v)};
}

// The pixel: its samples averaged (lbuffer, ao, shadow; the sky where most
// samples see it), the AO's standard error combined over them, and the
// standard error of the luminance's mean (spp_error; 0 for one sample).
void tracePixel(const Trace& t, int x, int row, TraceOutput& out, TileCounts& counts) {
    const size_t p = static_cast<size_t>(row) * t.camera.width + x;
    const int n = t.model.pixelSamples;
    glm::dvec3 radiance(0.0);
    double ao = 0.0, shadow = 0.0, aoVariance = 0.0, aoError = -1.0, lum = 0.0, lumSq = 0.0;
    int sky = 0, withAo = 0;
    for (int i = 0; i < n; ++i) {
        // Asked between samples too: a pixel of thousands of samples must not delay a cancel.
        if (t.cancel && (i & 15) == 15 && t.cancel->load(std::memory_order_relaxed)) return;
        const glm::dvec2 o = pixelOffset(t, p, i, n);
        SampleOutput s;
        // The first sample keeps the pixel's own AO pattern (one sample: the image it always was).
        const std::uint64_t seed = i == 0 ? p : mix64(p ^ (static_cast<std::uint64_t>(i) << 40));
        const glm::dvec3 c = traceSample(t, x, row, o.x, o.y, seed, s, counts);
        radiance += c;
        const double y = luminance(c.r, c.g, c.b);
        lum += y;
        lumSq += y * y;
        ao += s.ao;
        shadow += s.shadow;
        sky += s.sky ? 1 : 0;
        if (s.aoError >= 0.0) {
            aoVariance += s.aoError * s.aoError;
            aoError = s.aoError;
            ++withAo;
        }
    }
    radiance /= n;
    for (int c = 0; c < 3; ++c) out.images.lbuffer.pixels[p * 4 + c] = static_cast<float>(radiance[c]);
    out.images.ao.pixels[p] = static_cast<float>(ao / n);
    out.images.shadow.pixels[p] = static_cast<float>(shadow / n);
    out.images.background[p] = 2 * sky > n ? 1 : 0;
    if (withAo > 0) out.aoError[p] = withAo == 1 ? aoError : std::sqrt(aoVariance) / withAo;
    const double mean = lum / n;
    const double variance = n > 1 ? std::max(lumSq / n - mean * mean, 0.0) * n / (n - 1) : 0.0;
    out.images.sppError.pixels[p] = static_cast<float>(std::sqrt(variance / n));
}

// The AO estimate's standard error over the pixels that have one.
void aoErrorStatistics(const std::vector<double>& aoError, ReferenceStatistics& stats) {
    double sumErr = 0.0;
    long long counted = 0;
    for (double e : aoError)
        if (e >= 0.0) {
            sumErr += e;
            stats.aoStandardErrorMax = std::max(stats.aoStandardErrorMax, e);
            ++counted;
        }
    stats.aoStandardErrorMean = counted > 0 ? sumErr / counted : 0.0;
}

// The pixel estimate's standard error (of its luminance) over the image.
void sppErrorStatistics(const FloatImage& sppError, ReferenceStatistics& stats) {
    double sum = 0.0;
    for (float e : sppError.pixels) {
        sum += e;
        stats.sppErrorMax = std::max(stats.sppErrorMax, static_cast<double>(e));
    }
    stats.sppErrorMean = sppError.pixels.empty() ? 0.0 : sum / static_cast<double>(sppError.pixels.size());
}

void checkRequest(const ReferenceModel& model, const ReferenceRequest& request) {
    if (request.width < 1 || request.height < 1) throw Error("reference: the size must be at least 1x1");
    if (model.pixelSamples < 1) throw Error("reference: at least 1 sample per pixel");
    if (model.rayTracedAo && model.aoRays < 1) throw Error("reference: AO needs at least 1 ray per pixel");
}

}  // namespace

ReferenceImages renderReference(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request,
                                ReferenceProgress* progress, RaySceneCache* rayScenes) {
    checkRequest(model, request);
    const auto buildStart = Clock::now();
    std::shared_ptr<const RayScene> rays =
        rayScenes ? rayScenes->get(scene)
                  : std::make_shared<const RayScene>(scene, RayScene::sceneCentre(scene));
    const double buildSeconds = secondsSince(buildStart);
    ReferenceImages out = renderReference(scene, *rays, model, request, progress);
    out.stats.buildSeconds = buildSeconds;
    return out;
}

ReferenceImages renderReference(const Scene& scene, const RayScene& rays, const ReferenceModel& model,
                                const ReferenceRequest& request, ReferenceProgress* progress) {
    checkRequest(model, request);
    const int W = request.width, H = request.height;
    const glm::dvec3 cameraPosition(request.camera.position);
    ReferenceImages out;
    out.stats.triangles = rays.triangleCount();
    out.stats.threads = request.threads > 0 ? request.threads : tbb::this_task_arena::max_concurrency();
    const CameraRays camera(request.camera, W, H);
    Trace trace{scene,
                      rays,
                      model,
                      camera,
                      cameraPosition - rays.origin(),
                      lightsInView(scene, model, rays.origin(), cameraPosition, camera.worldToView),
                      SkyReference(scene, model),
                      glm::dvec3(scene.ambient)};
    if (progress) trace.cancel = &progress->cancel;

    out.lbuffer = makeImage(W, H, 4, 1.0f);
    out.ao = makeImage(W, H, 1, 1.0f);
    out.shadow = makeImage(W, H, 1, 1.0f);
    out.sppError = makeImage(W, H, 1, 0.0f);
    out.background.assign(static_cast<size_t>(W) * H, 0);
    std::vector<double> aoError(static_cast<size_t>(W) * H, -1.0);
    std::atomic<long long> shadowRays{0}, aoRays{0}, blendedHits{0};
    if (progress) {
        progress->totalPixels = static_cast<long long>(W) * H;
        progress->donePixels = 0;
    }

    const auto start = Clock::now();
    forEachTile(W, H, request.threads, progress, [&](const tbb::blocked_range2d<int>& r) {
        TraceOutput output{out, aoError};
        TileCounts counts;
        for (int row = r.rows().begin(); row < r.rows().end(); ++row)
            for (int x = r.cols().begin(); x < r.cols().end(); ++x) tracePixel(trace, x, row, output, counts);
        shadowRays += counts.shadow;
        aoRays += counts.ao;
        blendedHits += counts.layers;
    });
    if (progress && progress->cancel.load()) throw ReferenceCancelled();
    out.stats.blendedHits = blendedHits.load();
    out.stats.seconds = secondsSince(start);
    out.stats.primaryRays = static_cast<long long>(W) * H * model.pixelSamples;
    out.stats.pixelSamples = model.pixelSamples;
    sppErrorStatistics(out.sppError, out.stats);
    out.stats.shadowRays = shadowRays.load();
    out.stats.aoRays = aoRays.load();
    aoErrorStatistics(aoError, out.stats);
    out.final = toneMap(out.lbuffer, out.background, model);
    return out;
}

RayThroughput measureRayThroughput(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request,
                                   RaySceneCache* rayScenes) {
    const int W = request.width, H = request.height;
    const std::shared_ptr<const RayScene> shared =
        rayScenes ? rayScenes->get(scene) : std::make_shared<const RayScene>(scene, RayScene::sceneCentre(scene));
    const RayScene& rays = *shared;
    const glm::dvec3 cameraPosition(request.camera.position);
    const glm::dvec3 eye = cameraPosition - rays.origin();
    const CameraRays camera(request.camera, W, H);
    const std::vector<LightInView> lights =
        lightsInView(scene, model, rays.origin(), cameraPosition, camera.worldToView);
    std::atomic<long long> total{0};
    const auto start = Clock::now();
    forEachTile(W, H, request.threads, nullptr, [&](const tbb::blocked_range2d<int>& r) {
        long long local = 0;
        for (int row = r.rows().begin(); row < r.rows().end(); ++row)
            for (int x = r.cols().begin(); x < r.cols().end(); ++x) {
                const glm::dvec3 dir = camera.direction(x, row);
                const RayHit hit =
                    rays.intersect(eye, dir, camera.nearPlane, camera.farPlane, Visibility::Camera);
                ++local;
                if (!hit.hit) continue;
                const glm::uvec3 tri = rays.triangle(hit.instance, hit.triangle);
                const auto& P = rays.instances()[hit.instance].positions;
                const glm::dvec3 q =
                    (1.0 - hit.u - hit.v) * P[tri.x] + hit.u * P[tri.y] + hit.v * P[tri.z];
                glm::dvec3 ng =
                    glm::normalize(glm::cross(P[tri.y] - P[tri.x], P[tri.z] - P[tri.x]));
                if (glm::dot(ng, dir) > 0.0) ng = -ng;
                const glm::dvec3 origin = q + ng * offsetAt(q, q - eye, rays.sceneRadius());
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
