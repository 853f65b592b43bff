#pragma once
// The CPU ground truth (DESIGN.md "The measuring half"; issue "Ground truth
// and error metrics"): the GPU's shading model without its approximations,
// evaluated in double precision on exact geometry traced with Embree.
//
// Per pixel: one ray through the pixel centre (as the rasteriser samples),
// clipped to the camera's near and far planes; the hit recomputed in double
// from its triangle and barycentrics; the material as the G-buffer pass
// evaluates it (MaterialEvaluator) without the G-buffer's quantisation; every
// enabled light by ShadingReference::shadeLight with no volume cut-off (the
// classic attenuation) or with Ferko's window at the threshold's radius (the
// windowed model); hard shadows by a ray to each shadow-casting light; the
// ambient term k_a i_a scaled by the accessibility A and the baked occlusion,
// plus emission; the sky where no geometry is. Blended materials (glTF
// BLEND) are composited front to back along the primary ray in exact depth
// order, premultiplied "over" (C = a C_s + (1 - a) C_d), each shaded like an
// opaque surface but without AO; they cast no shadow and occlude no AO.
//
// Ambient occlusion (when the model has it) is the integral
//     A = 1 - intensity * (1/pi) Int_{hemisphere(N)} V_R(w) / (1 + (d(w)/R)^2) cos(theta) dw,
// V_R(w) = 1 where a surface lies within the AO radius R along w (d(w) its
// distance), estimated with `aoRays` cosine-weighted rays (a Hammersley set
// rotated per pixel; fixed seed) and clamped to [0, 1]. Its standard error per
// pixel is estimated from the samples (for a stratified set this is an upper
// bound). Directions below the geometric surface count as occluded at d = 0.
//
// Outputs: all W x H, rows top-down (as written to files), in linear radiance:
//   lbuffer  RGBA, A = 1 (HDR L-buffer: what the GPU's `lbuffer` holds)
//   final    RGBA in [0, 1]: the tone-mapped lbuffer (ToneMapReference), sRGB-encoded as the GPU's `final`
//   ao       1 channel: the accessibility A (1 where the model has no AO, and on the sky)
//   shadow   1 channel: the fraction of the shadow-casting lights' direct light (luminance) that reaches the
//            point; 1 where no such light reaches it, and on the sky
//   spp_error 1 channel: the standard error of the pixel's luminance estimate, from the spread of its
//            samples (0 with one sample; for the stratified set an upper bound, as for the AO)
// Samples per pixel (ReferenceModel::pixelSamples, reference --spp): one ray
// through the pixel centre by default; N > 1 samples the pixel filter's
// footprint at N points (Hammersley, rotated per pixel by the seed) and
// averages everything each finds (radiance, AO, shadow); the sky flag where
// most samples see the sky. Each sample traces the model's AO rays.
// Deterministic: the same image for any thread count. Cancellable through
// ReferenceProgress (ReferenceCancelled is thrown).
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/Error.h"
#include "renderer/io/ImageIO.h"
#include "renderer/reference/ReferenceModel.h"
#include "renderer/scene/Camera.h"
#include "renderer/scene/Scene.h"

namespace dw::reference {

class RayScene;
class RaySceneCache;

class ReferenceCancelled : public Error {
public:
    ReferenceCancelled() : Error("reference render cancelled") {}
};

// Shared with whoever watches a render: the renderer counts finished pixels
// and stops soon after `cancel` is set.
struct ReferenceProgress {
    std::atomic<long long> donePixels{0};
    std::atomic<long long> totalPixels{0};
    std::atomic<bool> cancel{false};
    double fraction() const {
        const long long t = totalPixels.load();
        return t > 0 ? static_cast<double>(donePixels.load()) / static_cast<double>(t) : 0.0;
    }
};

struct ReferenceStatistics {
    double seconds = 0.0;       // wall time of the render (not the Embree build)
    double buildSeconds = 0.0;  // Embree scene build
    int threads = 0;
    long long primaryRays = 0, shadowRays = 0, aoRays = 0;
    long long blendedHits = 0;  // blended surfaces composited (extra primary-ray hits)
    double aoStandardErrorMean = 0.0;  // mean over surface pixels of the per-pixel standard error of A
    double aoStandardErrorMax = 0.0;
    int pixelSamples = 1;       // samples per pixel (ReferenceModel::pixelSamples)
    double sppErrorMean = 0.0;  // over all pixels, the standard error of the pixel's luminance estimate (spp_error)
    double sppErrorMax = 0.0;
    size_t triangles = 0;
    long long rays() const { return primaryRays + shadowRays + aoRays; }
};

struct ReferenceImages {
    FloatImage lbuffer, final, ao, shadow;
    FloatImage sppError;  // 1 channel: the standard error of the pixel's luminance (0 with one sample)
    std::vector<std::uint8_t> background;  // 1 where the pixel sees the sky
    ReferenceStatistics stats;
    // The image by buffer name: "lbuffer", "final", "ao", "shadow" or "spp_error"; nullptr otherwise.
    const FloatImage* buffer(const std::string& name) const;
};

// Whether the samples per pixel are enough (issue 35's rule): the mean over
// pixels of the luminance estimate's relative standard error, spp_error /
// (L + 1e-3), against half an 8-bit step (0.5 / 255): below it, more samples
// move the final image by less than its display resolution. One line:
// "pixel samples: 16 (box), relative standard error mean 0.0012 (max 0.31):
// enough (under 0.00196)" or "... not enough ...: try --spp 64".
std::string pixelSamplesVerdict(const ReferenceImages& images, const ReferenceModel& model);
// The figure the verdict reads: the mean over pixels of spp_error / (L + 1e-3).
double meanRelativeSppError(const ReferenceImages& images);
constexpr double kSppEnough = 0.5 / 255.0;  // the verdict's threshold: half an 8-bit step

// The buffer names a reference has, in order.
const std::vector<std::string>& referenceBuffers();

struct ReferenceRequest {
    Camera camera;
    int width = 640, height = 360;
    int threads = 0;  // 0: all the machine has
};

// The threads a render can run at once (oneTBB's default concurrency).
int availableThreads();

// The geometry is traced on the scene's RayScene, relative to the scene's
// centre: `rayScenes` holds it across renders (every camera of a sweep
// shares one build, RaySceneCache.h); null: one built for this render alone.
// Either way the same image. stats.buildSeconds: the time getting the ray
// scene took (near 0 when it was held).
// Throws Error (Embree failures, a size below 1x1) or ReferenceCancelled.
ReferenceImages renderReference(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request,
                                ReferenceProgress* progress = nullptr, RaySceneCache* rayScenes = nullptr);
// On a given ray scene, built from `scene`'s content with its origin anywhere
// (RayScene::sceneCentre as above; a camera's position for the per-camera
// frame every reference used before issue 33). stats.buildSeconds is 0.
ReferenceImages renderReference(const Scene& scene, const RayScene& rays, const ReferenceModel& model,
                                const ReferenceRequest& request, ReferenceProgress* progress = nullptr);

// Embree alone over the rays a reference render casts: the same primary rays;
// at each primary hit, a shadow ray to every shadow-casting light (when the
// model has shadows) and the model's AO rays (the same directions about the
// geometric normal), with no material, shading or statistics. The reference's
// rays per second divided by this says how much the shading and sampling add
// to the ray queries (1: nothing).
struct RayThroughput {
    long long rays = 0;
    double seconds = 0.0;
    double raysPerSecond() const { return seconds > 0.0 ? static_cast<double>(rays) / seconds : 0.0; }
};
RayThroughput measureRayThroughput(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request,
                                   RaySceneCache* rayScenes = nullptr);

}  // namespace dw::reference
