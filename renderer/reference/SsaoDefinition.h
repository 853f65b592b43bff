#pragma once
// SSAO's own estimator (shaders/ssao/ssao.frag: 1 - intensity x the mean over
// kernel points of the falloff 1 / (1 + (d/R)^2) where the first surface seen
// through the point lies in front of it) evaluated exactly: exact positions
// and normals instead of the G-buffer, the first surface through each kernel
// point by a camera ray instead of the filtered depth buffer, and the random
// rotation averaged over many directions instead of a 4x4 noise tile, at full
// resolution without a blur. The difference between this and the ray-traced
// AO (ReferenceRenderer) is the part of SSAO's error that comes from its
// definition; the rest (depth-buffer sampling, the noise tile, resolution,
// blur) is the difference between this and the GPU's SSAO. docs/reference.md
// gives both, measured.
#include "renderer/io/ImageIO.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/reference/ReferenceRenderer.h"

namespace dw::reference {

struct SsaoDefinitionSettings {
    int kernelSize = 16;     // ssao.samples: SsaoMethod::kernel(kernelSize)
    int rotations = 16;      // random reflection vectors averaged per pixel
    double radius = 1.0;     // world units (ssao.radius in ssao.radius_unit)
    double intensity = 1.0;  // ssao.intensity
    double bias = 0.025;     // ssao.bias, a fraction of the radius
    bool rangeCheck = true;  // ssao.range_check
    std::uint32_t seed = 1;
    static SsaoDefinitionSettings fromKnobs(const KnobRegistry& knobs, const Scene& scene);
};

// W x H, 1 channel, rows top-down: the accessibility, 1 on the sky.
FloatImage ssaoDefinitionAo(const Scene& scene, const ReferenceRequest& request, const SsaoDefinitionSettings& settings,
                            ReferenceProgress* progress = nullptr);

}  // namespace dw::reference
