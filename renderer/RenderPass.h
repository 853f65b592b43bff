#pragma once
// One pass of the pipeline (Falcor's RenderPass, Filament's frame-graph pass):
// it declares its knobs and named inputs/outputs, says when it cannot run, owns
// its GL resources, and executes. The Pipeline, not the pass, decides whether
// it runs, times it, and resets GL state around it.
#include <string>
#include <vector>

#include "renderer/FrameContext.h"
#include "renderer/OutputRegistry.h"

namespace dw {

class KnobRegistry;
class GpuScene;

struct PassIO {
    std::vector<std::string> inputs;          // must have been produced this frame
    std::vector<std::string> optionalInputs;  // used when produced
};

class RenderPass {
public:
    virtual ~RenderPass() = default;
    virtual const char* name() const = 0;
    // Outputs, known before any GL exists (for `list buffers` and the inspector).
    virtual std::vector<OutputDecl> outputs() const = 0;
    // Inputs may depend on the knobs (e.g. the tone mapper reads luminance
    // statistics only for operators that need them).
    virtual PassIO inputs(const KnobRegistry& knobs) const = 0;
    // Non-empty when the pass cannot or should not run: switched off, or the
    // scene has nothing for it. Shown in the inspector as the skip reason.
    virtual std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const {
        (void)knobs;
        (void)scene;
        return {};
    }
    // Creates programs and size-independent GL objects. Called once with a context.
    virtual void setup(gl::ShaderLibrary& shaders) = 0;
    // (Re)creates size-dependent targets and binds them in `outputs`.
    virtual void resize(int width, int height, OutputRegistry& outputs) = 0;
    virtual void execute(FrameContext& ctx) = 0;
    // A line for the inspector about the last execution ("36 lights: 30 volumes, 6 culled").
    virtual std::string stats() const { return {}; }
};

}  // namespace dw
