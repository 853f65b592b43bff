#pragma once
// Reads every produced output at one pixel, and decodes the G-buffer there:
// depth, reconstructed view and world position, normal, albedo, specular
// colour and exponent, emission, L-buffer radiance. New outputs (AO, sample
// counts) appear in `values` without code here, whatever their kind: a
// multisample output with every sample, a per-pixel buffer with its element.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "renderer/graph/OutputRegistry.h"

namespace dw {

class Pipeline;

struct ProbeValue {
    std::string output;
    OutputKind kind = OutputKind::Color;
    int channels = 4;
    glm::vec4 raw{0.0f};  // as the shaders see it (sRGB decoded); multisample: the mean of the samples
    std::vector<glm::vec4> samples;     // multisample outputs: every sample, in order
    std::vector<std::uint32_t> words;   // per-pixel buffers: the element's 4-byte words; `raw` holds the
                                        // first four as floats, or as integers for Count outputs
};

struct SurfaceSample {
    bool background = true;
    float depth = 1.0f;
    float linearDepth = 0.0f;  // distance along the view axis
    glm::vec3 viewPosition{0.0f}, worldPosition{0.0f};
    glm::vec3 viewNormal{0.0f};
    glm::vec3 albedo{0.0f}, specular{0.0f}, emissive{0.0f};
    float exponent = 0.0f;
    glm::vec3 radiance{0.0f};  // L-buffer
    float luminance = 0.0f;
};

// A transparent fragment the oit pass kept at the pixel (issue 21).
struct TransparentFragment {
    float depth = 0.0f;          // window depth
    glm::vec3 colour{0.0f};      // lit colour (the stored premultiplied colour / alpha)
    float alpha = 0.0f;
};

struct ProbeResult {
    int x = 0, y = 0;  // pixel, rows top-down
    bool inside = false;
    SurfaceSample surface;
    std::vector<ProbeValue> values;
    // The pixel's transparent fragments, nearest first, from the method that
    // keeps them this frame (the linked list's nodes, the A-buffer's
    // samples); `fragmentsFrom` names it, empty when no method kept any.
    std::vector<TransparentFragment> fragments;
    std::string fragmentsFrom;
};

// x, y in pixels with y = 0 at the top. Blocks on the GPU (a read-back).
ProbeResult probePixel(const Pipeline& pipeline, int x, int y);

}  // namespace dw
