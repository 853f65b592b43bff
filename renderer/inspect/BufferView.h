#pragma once
// Turns any named output into a displayable RGBA8 image, on the GPU: the
// inspector and viewport show these, and `render --buffer X --out x.png`
// writes them. Reading needs no per-pass code: the output's kind picks the
// default mapping (depth linearised, normals as colours, counts as a heat map,
// HDR tone-mapped); every choice can be overridden. Every resource kind is
// shown, laid out as ImageLayout (OutputReadback.h) describes: a multisample
// texture resolved or per sample, an array or 3D texture as a grid of layers
// or one layer, a cube as an unfolded cross, a per-pixel buffer as an image
// and any other buffer as a table of its words.
#include <glm/glm.hpp>
#include <string>

#include "renderer/inspect/OutputReadback.h"
#include "renderer/graph/OutputRegistry.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "shaders/params/bufferview.h"

namespace dw {

struct BufferViewSettings {
    // NonFinite: NaN magenta, +Inf red, -Inf blue, finite values dim grey
    // (where a NaN entered; FiniteCheck counts them).
    enum class Mapping { Auto = -1, Direct = 0, LinearDepth = 1, Normal = 2, Heatmap = 3, Tonemap = 4, NonFinite = 5 };
    enum class Channel { RGB = 0, R = 1, G = 2, B = 3, A = 4 };
    Mapping mapping = Mapping::Auto;
    Channel channel = Channel::RGB;
    int autoRange = -1;  // -1: by kind, 0: manual range, 1: automatic min/max
    float rangeMin = 0.0f, rangeMax = 1.0f;
    float exposure = 0.0f;  // EV, tone-mapped view
    float nearPlane = 0.1f, farPlane = 100.0f;  // for linear depth
    bool reversedDepth = true;  // the depth.mode of the frame shown (DepthConvention)
    int layer = -1;   // arrays, 3D: one layer (slice); cube arrays: one cube; -1: all, in a grid
    int sample = -1;  // multisample: one sample; -1: resolved (the mean of the samples)
    ViewSelection selection() const { return {layer, sample}; }
};

class BufferView {
public:
    void setup(gl::ShaderLibrary& shaders);
    // Renders `output` with `settings` into an RGBA8 texture of the output's
    // size, or of its grid, cross or table (imageLayout). Throws dw::Error if
    // the output is not allocated.
    const gl::Texture& render(const PublishedOutput& output, const BufferViewSettings& settings);
    // The mapping actually used for an output kind under `settings`.
    static BufferViewSettings::Mapping resolveMapping(OutputKind kind, const BufferViewSettings& s);
    static bool resolveAutoRange(OutputKind kind, const BufferViewSettings& s);
    // Per-channel range found by the last auto-range render (reads back 32 bytes).
    std::pair<glm::vec4, glm::vec4> lastAutoRange() const;
    const gl::Texture& texture() const { return target_; }

private:
    struct Programs {
        gl::ShaderLibrary::Handle view, minmaxFirst;
    };
    // One program pair per source kind (2D, multisample, array, 3D, buffer)
    // and value type (float, unsigned, signed), compiled when first needed.
    static constexpr int kSourceKinds = 5, kValueTypes = 3;
    const Programs& programs(int sourceKind, int valueType);
    gl::ShaderLibrary* shaders_ = nullptr;
    Programs programs_[kSourceKinds][kValueTypes];
    gl::ShaderLibrary::Handle minmaxNext_;
    gl::Texture sourceView_;  // layered sources: a view without compare mode (cubes as 2D arrays)
    gl::FullscreenTriangle triangle_;
    gl::ParamBuffer<gpu::BufferViewParams> params_;
    gl::Buffer ping_, pong_;
    const gl::Buffer* result_ = nullptr;
    gl::Texture target_;
    gl::Framebuffer fbo_;
};

}  // namespace dw
