#pragma once
// How the ao pass computes the ambient accessibility ao.raw (issue 22): one
// class per method, each a value of the knob ao.method, like the OIT methods
// and the lighting strategies. Every method reads the G-buffer (and whatever
// else it names in inputs()) and writes ao.raw, R16F, 1 = open, at the size
// its resolutionShift() gives; the shared filter (ao_filter) blurs and
// upsamples it to ao.filtered, which the lighting pass multiplies into the
// ambient term. Buffers of a method's own are named after it (ssao.*,
// gtao.*, aov.*) and allocated only while ao.method names it. A new method is
// one class and one registration line in BuiltinAoMethods.cpp (or, from
// outside the library, static dw::RegisterAoMethod<MyMethod> registerMine;).
// The constructor declares the method's knobs (ssao.*, gtao.*, aov.*) in the
// registry and lists their names in knobNames().
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "renderer/gl/ShaderLibrary.h"
#include "renderer/graph/FrameContext.h"
#include "renderer/graph/MethodSet.h"
#include "renderer/graph/OutputRegistry.h"

namespace dw {

class KnobRegistry;

class AoMethod {
public:
    virtual ~AoMethod() = default;
    // The knob value (ao.method = name).
    virtual const char* name() const = 0;
    // One sentence for `list knobs` and the parameter tooltip.
    virtual std::string description() const = 0;
    // The knobs the constructor declared (for the reference's knob report
    // and the panels).
    virtual std::vector<std::string> knobNames() const = 0;
    // Outputs of its own (allocated only while ao.method names it).
    virtual std::vector<OutputDecl> outputs() const { return {}; }
    virtual ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const {
        (void)knobs;
        return output.resource;
    }
    // Whether an own output exists under the knobs while the method is
    // chosen (GTAO's gtao.noisy only with its own denoise); by default all.
    virtual bool allocates(const OutputDecl& output, const KnobRegistry& knobs) const {
        (void)output;
        (void)knobs;
        return true;
    }
    // What it reads besides nothing: by default gbuffer.depth and gbuffer.normal.
    virtual std::vector<std::string> inputs(const KnobRegistry& knobs) const {
        (void)knobs;
        return {"gbuffer.depth", "gbuffer.normal"};
    }
    // ao.raw's size under the knobs: the frame's size >> shift (0 full, 1 half, 2 quarter).
    virtual int resolutionShift(const KnobRegistry& knobs) const {
        (void)knobs;
        return 0;
    }
    // Whether the shared filter blurs ao.raw (by ssao_blur.*) before
    // upsampling it; false when the method denoised it itself or its own
    // knob turns the blur off. The upsampling to full size happens anyway.
    virtual bool sharedBlur(const KnobRegistry& knobs) const {
        (void)knobs;
        return true;
    }
    virtual void setup(gl::ShaderLibrary& shaders) = 0;
    // Writes ao.raw (ctx.texture("ao.raw"), already allocated at
    // resolutionShift) and its own outputs. GL state is reset around the pass.
    virtual void run(FrameContext& ctx) = 0;
    // A line for the inspector about the last run ("16 samples at 80x45, ...").
    virtual std::string stats() const = 0;
};

// The family's registration is graph/MethodSet's, as every method family's.
using AoMethodFactory = MethodFactory<AoMethod>;
using AoMethodCatalog = MethodCatalog<AoMethod>;

// The built-in methods, in the order of ao.method's choices (BuiltinAoMethods.cpp);
// the first is the default.
std::vector<AoMethodFactory> builtinAoMethods();

template <typename T>
using RegisterAoMethod = RegisterMethod<AoMethod, T>;

}  // namespace dw
