#pragma once
// The frame's lights, as every lighting strategy and the shadow pass see them
// (DESIGN.md "Resources and strategies"): one row per enabled light that can
// reach the threshold, with its volume radius (seed 001 eq. 1) and whether
// that volume meets the view frustum. The CPU side keeps the row order and the
// volumes; the GPU side is the std430 SSBO `lights.table` (binding
// LIGHT_SSBO, shaders/common/lighting.glsl), uploaded once per frame and
// patched row by row when a reused shadow map is re-rendered for a light.
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "renderer/lighting/LightVolume.h"
#include "renderer/gl/Buffer.h"
#include "renderer/scene/Light.h"
#include "shaders/params/light.h"

namespace dw {

// A row of the table: gpu::Light (shaders/params/light.h, what
// shaders/common/lighting.glsl reads), with identity matrices and zero vectors.
struct LightGpu : gpu::Light {
    LightGpu() : gpu::Light{glm::mat4(1.0f), glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(0.0f),
                            glm::mat4(1.0f), glm::vec4(0.0f), glm::vec4(0.0f)} {}
};
static_assert(sizeof(LightGpu) == sizeof(gpu::Light), "the table's rows are gpu::Light");

// The kind in a row's attenuation.w of a spot light whose falloff is
// SpotFalloff::InnerOuterCone (0, 1 and 2 are directional, point and spot
// with cutoff and exponent).
constexpr int kLightKindSpotCone = gpu::LIGHT_SPOT_CONE;

// What such a row holds in intensityExponent.w: 1 / (cos inner - cos outer),
// worked out in double (the shader's ramp is (cos theta - cos outer) times
// it), 1e30 for equal cones (a hard edge).
float coneRampScale(const Light& light);

struct LightTableEntry {
    int row = 0;                 // index into rows (and the SSBO)
    const Light* light = nullptr;
    LightVolume volume;
    bool inFrustum = true;       // the volume's bounding sphere meets the view frustum
    bool shadowed = false;       // gets a shadow map this frame (set by the shadow pass)
};

// Directional lights the G-buffer pass shades when
// lighting.directional_in_gbuffer is on (seed 000 section 3.2.1: "possibly
// generating the results during the G-Buffer pass"): the enabled directional
// rows without a shadow map this frame (`shadows`: FrameContext::shadows is
// set), the first kMaxGBufferDirectional of them in table order. The lighting
// pass skips exactly these; lights with a map stay there (a reused map exists
// only while its light is shaded).
constexpr int kMaxGBufferDirectional = 8;  // MAX_GBUFFER_DIRECTIONAL in geometry.frag
struct LightTable;
std::vector<int> gbufferDirectionalRows(const LightTable& table, bool shadows);

struct LightTable {
    std::vector<LightGpu> rows;
    std::vector<LightTableEntry> entries;  // one per row, in scene order
    int belowThreshold = 0;                // enabled lights that never reach the threshold
    gl::Buffer* buffer = nullptr;          // the SSBO behind lights.table

    // Uploads one row again (after its shadow lookup changed).
    void uploadRow(int row) const;
};

}  // namespace dw
