#pragma once
// What the CPU reference renders: the knobs that define the shading model
// (honoured), and the ones that only choose how the GPU approximates it
// (ignored). DESIGN.md "The measuring half": a reference is the same model
// without the approximation.
//
// Honoured: shadows.enabled (hard shadows by rays for the lights whose shadow
// flag is set) and shadows.blended_casters, ao.enabled with the radius of the
// method ao.method names (ssao.radius in ssao.radius_unit and ssao.intensity,
// gtao.radius in gtao.radius_unit, ...: ambient occlusion by rays), lighting.attenuation,
// lighting.window_exponent and, for the windowed model only,
// lighting.threshold (the window's radius is part of that model),
// lighting.ambient_specular, lighting.ambient_occlusion, skybox.*, tonemap.*
// and luminance.* (the final image's tone mapping).
// Not modelled: bloom, depth of field and FXAA (effects after the L-buffer;
// compare a final image with them off).
// Ignored: every other knob (strategy, threshold under the classic model,
// G-buffer formats, map sizes, PCF, AO samples, slices, steps and resolution, ...).
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/knobs/KnobRegistry.h"
#include "renderer/reference/ShadingReference.h"
#include "renderer/scene/Scene.h"

namespace dw::reference {

enum class ToneOperator { Simple, Reinhard, Aces, Neutral, Clamp };
enum class SkyChoice { Color, Procedural, Equirect, Cube };
// How a pixel's samples are weighted (reference --filter): box, the pixel's
// square; tent, a triangle of radius 1 px about its centre (samples drawn
// from it, so its footprint is 2 px wide and every sample weighs the same).
enum class PixelFilter { Box, Tent };
// "box" -> PixelFilter::Box, "tent" -> Tent; Error naming the filters otherwise.
PixelFilter pixelFilterNamed(const std::string& name);
const char* pixelFilterName(PixelFilter filter);

struct ReferenceModel {
    AttenuationModel attenuation = AttenuationModel::Classic;
    double windowExponent = 20.0;
    double threshold = 1.0 / 255.0;  // only for AttenuationModel::Windowed (the window's radius)
    bool shadows = true;
    bool blendedCasters = false;  // shadows.blended_casters: blended materials cast shadows as if opaque
    bool ambientSpecular = true;
    bool bakedOcclusion = true;  // lighting.ambient_occlusion = both or baked
    bool rayTracedAo = true;     // ao.enabled and lighting.ambient_occlusion = both or screen
    double aoRadius = 1.0;       // world units (the ao.method's radius, e.g. ssao.radius in ssao.radius_unit)
    double aoIntensity = 1.0;
    int aoRays = 64;             // cosine-weighted rays per pixel
    std::uint32_t seed = 1;      // the AO sample pattern's and the pixel samples'
    // Samples per pixel (reference --spp): 1 traces the pixel's centre (the
    // rasteriser's sample); N > 1 traces N points of a low-discrepancy set
    // (Hammersley, shifted per pixel by a seeded Cranley-Patterson rotation)
    // over the filter's footprint and averages them: the integral over the
    // pixel, textures read at their base level at each point.
    int pixelSamples = 1;
    PixelFilter pixelFilter = PixelFilter::Box;
    SkyChoice sky = SkyChoice::Color;
    double skyIntensity = 1.0;   // skybox.intensity x the scene's
    double skyRotationDegrees = 0.0;
    // Tone mapping (shaders/tonemap/tonemap.frag) and its statistics (luminance.*).
    ToneOperator toneOperator = ToneOperator::Reinhard;
    double key = 0.18, white = 4.0, exposure = 0.0;
    bool autoWhite = true, autoExposure = false, srgb = true, nanGuard = true;
    double logDelta = 1e-4;
    bool backgroundInStatistics = true;

    // From knob values (RunConfig::applyKnobs has set them) and the scene
    // (its bounds set the AO radius's unit; its sky what skybox.mode = scene means).
    static ReferenceModel fromKnobs(const KnobRegistry& knobs, const Scene& scene);

    // Every value above as "name=value;" text, in a fixed order: the cache key's model part.
    std::string canonical() const;

    // The knobs the reference honours (the names fromKnobs reads).
    static const std::vector<std::string>& honouredKnobs();
    // The knobs of effects after the L-buffer it does not model (bloom, DoF, FXAA on/off).
    static const std::vector<std::string>& unmodelledKnobs();
};

// What a reference run says about the knobs it was given: those it ignored
// that differ from their defaults, and the effects that are on but not modelled.
struct KnobReport {
    std::vector<std::string> ignoredChanged;  // "lighting.strategy=tiled"
    int ignoredTotal = 0;
    std::vector<std::string> unmodelledOn;    // "bloom.enabled"
    std::string text() const;
};
// `model`: what the knobs made (the threshold is ignored under the classic
// model); `finalImage`: whether the run writes the final image (the effects
// not modelled matter only there).
KnobReport reportKnobs(const KnobRegistry& knobs, const ReferenceModel& model, bool finalImage = true);

}  // namespace dw::reference
