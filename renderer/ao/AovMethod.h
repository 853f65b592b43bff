#pragma once
// Ambient Occlusion Volumes, ao.method = aov (McGuire 2010, "Ambient
// Occlusion Volumes", HPG; seed 000 sections 4.6.4 and 5.7, tables 6.5 and
// 6.7). Reads gbuffer.depth, gbuffer.normal and the scene's opaque and MASK
// triangles (blended ones cast no volume); writes aov.depth (gbuffer.depth at
// the AO size), aov.occlusion (the summed occlusion of every volume that
// covers the pixel), aov.overdraw (fragments shaded per pixel, when asked
// for) and ao.raw = 1 - clamp(aov.occlusion), at aov.resolution (full, 1/2
// or 1/4). The shared filter only upsamples it (cross-bilateral): the
// volumes are not sampled, so there is no noise to blur.
//
// A geometry shader (shaders/ao/aov_volume.geom) extrudes each triangle's
// volume; its fragment stage evaluates the analytic form factor of the part
// of the triangle the G-buffer point sees within aov.radius, times a
// distance weight to the power aov.falloff (shaders/ao/aov_volume.frag gives
// the derivation). Volumes the camera is
// inside of (within the near plane's reach) are drawn as back faces with the
// depth test reversed, in a second draw, so the image stays right there;
// docs/ao.md has the measured cost. The geometry shader drops volumes
// wholly outside the view frustum; aov.radius is in aov.radius_unit (world,
// or the scene's power-of-ten unit). What a frame will cost is estimated on
// the CPU by AovCostEstimate (docs/aov.md, "Cost on a large model").
#include <string>
#include <vector>

#include "renderer/ao/AoMethod.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "shaders/params/aov.h"

namespace dw {

struct Bounds;

class AovMethod : public AoMethod {
public:
    explicit AovMethod(KnobRegistry& knobs);
    const char* name() const override { return "aov"; }
    std::string description() const override;
    std::vector<std::string> knobNames() const override;
    std::vector<OutputDecl> outputs() const override;
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    int resolutionShift(const KnobRegistry& knobs) const override { return knobs.get(resolution_); }
    // Nothing to denoise: the shared filter only upsamples.
    bool sharedBlur(const KnobRegistry&) const override { return false; }
    void setup(gl::ShaderLibrary& shaders) override;
    void run(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

    // The camera's distance to its near plane's corners: a volume whose face
    // planes all lie within this of the camera may be cut by the near plane
    // and is drawn by its back faces.
    static float insideMargin(const CameraUniforms& camera);
    // aov.radius in world units: as given (aov.radius_unit = world) or times
    // the scene's power-of-ten length unit (scene_fraction; sceneLengthUnit).
    float worldRadius(const KnobRegistry& knobs, const Bounds& bounds) const;

private:
    FloatKnob radius_, falloff_;
    EnumKnob radiusUnit_, resolution_;
    gl::ShaderLibrary::Handle volume_, depthCopy_, resolve_;
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::AovParams> params_;
    TargetFramebuffer depthTarget_, volumeTarget_, rawTarget_;
    std::string stats_;
};

}  // namespace dw
