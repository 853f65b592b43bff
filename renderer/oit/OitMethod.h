#pragma once
// How the oit pass composites the blended materials over the L-buffer
// (seed 000 sections 3.4-3.5 and 5.8-5.9, seed 002 section 4, seed 003
// section 3.4): one class per method, each a value of the knob oit.method,
// like the lighting strategies. Every method forward-shades the transparent
// fragments with the same shader (shaders/oit/transparent.frag) and ends by
// blending (C, T), the layers' premultiplied colour and transmittance, over
// the L-buffer; they differ in how they order the fragments, what they lose
// and what they cost. A new method is one class and one registration line
// in BuiltinOitMethods.cpp (or, from outside the library,
//     static dw::RegisterOitMethod<MyMethod> registerMine;).
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Texture.h"
#include "renderer/graph/FrameContext.h"
#include "renderer/graph/MethodSet.h"
#include "renderer/graph/OutputRegistry.h"
#include "shaders/params/oit.h"

namespace dw {

class KnobRegistry;

// The image units, storage blocks and texture units of shaders/oit/*.frag
// are named in shaders/common/bindings.glsl (binding::OIT_*).

// One frame of a method's work, set up by the oit pass: the lighting
// block, the light table, gbuffer.depth (binding::GBUFFER_DEPTH_TEXTURE), the shadow maps when
// `shadowed`, oit.sample_count and oit.overflow cleared and bound to their
// image units; `params` uploaded at OIT_UBO.
struct OitFrame {
    FrameContext& ctx;
    // The blended instances in view (indices into GpuScene::draws()), in scene order.
    std::vector<std::size_t> draws;
    // forward_sorted: each double-sided object's back faces before its front faces.
    bool backFacesFirst = false;
    // Every shadow map was kept this frame: the shadowed shader variant.
    bool shadowed = false;
    gpu::OitParams params{};
    // Uploads `params` (after a method changed them).
    std::function<void()> uploadParams;
    // Blends the bound program's (C, T) over the L-buffer with a full-screen
    // triangle: L = C + T L, the L-buffer's alpha kept.
    std::function<void(const gl::Program&)> compositeOverLBuffer;
    // The transparent shader for `method` (METHOD_LIST, ...), shadowed or not as this frame needs.
    std::function<const gl::Program&(const std::string& method)> transparentProgram;
    void drawTransparent(const gl::Program& program) const;
};

class OitMethod {
public:
    virtual ~OitMethod() = default;
    // The knob value (oit.method = name).
    virtual const char* name() const = 0;
    // One sentence for `list knobs` and the parameter tooltip.
    virtual std::string description() const = 0;
    // Outputs of its own (allocated only while oit.method names it).
    virtual std::vector<OutputDecl> outputs() const { return {}; }
    virtual ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const {
        (void)knobs;
        return output.resource;
    }
    virtual void setup(gl::ShaderLibrary& shaders) { (void)shaders; }
    // Whether every fragment must be counted into oit.sample_count even when
    // no one looks at it (the A-buffer's exact overflow).
    virtual bool needsFragmentCount() const { return false; }
    virtual void render(OitFrame& frame) = 0;
    // What the last frame did, with the method's GPU memory at the current size.
    virtual std::string stats() const = 0;
    // Where the last frame's lost fragments went (the limits that dropped
    // them, with their knob values), for the warning the oit pass gives when
    // any were lost; methods that keep every fragment (weighted,
    // forward_sorted) say nothing.
    virtual std::string lossCause() const { return {}; }
};

// The family's registration is graph/MethodSet's, as every method family's.
using OitMethodFactory = MethodFactory<OitMethod>;
using OitMethodCatalog = MethodCatalog<OitMethod>;

// The built-in methods, in the order of oit.method's choices (BuiltinOitMethods.cpp).
std::vector<OitMethodFactory> builtinOitMethods();

template <typename T>
using RegisterOitMethod = RegisterMethod<OitMethod, T>;

// Bytes of the outputs `names` as allocated now ("3.2 MiB" in the statistics).
std::size_t allocatedBytes(const FrameContext& ctx, const std::vector<std::string>& names);
std::string mebibytes(std::size_t bytes);

}  // namespace dw
