#pragma once
// One pass of the pipeline (Falcor's RenderPass, Filament's frame-graph pass):
// it declares its knobs and its named inputs and outputs, says when it cannot
// run, owns its programs, and executes. The Pipeline, not the pass, decides
// whether and in which order it runs (from the read / write / modify edges),
// allocates its managed outputs, times it, and resets GL state around it.
#include <string>
#include <vector>

#include "renderer/graph/FrameContext.h"
#include "renderer/graph/OutputRegistry.h"

namespace dw {

class KnobRegistry;
class GpuScene;

// Where a pass stands in seed 002 section 6's order. Edges order the passes;
// the stage breaks ties and defines the post chain: passes of stage Post take
// the current display image (kCurrentImage) and produce the next one.
enum class PassStage { GBuffer, Screen, Lights, Lighting, Hdr, Tonemap, Post };
const char* toString(PassStage stage);

// In a Post pass's inputs: "the image the chain has so far" (the tone mapper's
// result, or the output of the post pass before this one).
inline constexpr const char* kCurrentImage = "@image";

struct PassIO {
    std::vector<std::string> inputs;          // must have been produced this frame
    std::vector<std::string> optionalInputs;  // used when produced
    std::vector<std::string> modifies;        // read and added into (another pass's output)
};

// How a pass asks the pipeline to sample the frame (anti-aliasing): render
// every frame-sized resource at `scale` times the output size per axis (SSAA;
// the pass's own outputs shift back down to the output size), and move the
// projection by `jitter` (in pixels of the rendered frame, each component in
// [-0.5, 0.5]) this frame (TAA). The default asks for neither.
struct FrameSampling {
    int scale = 1;
    glm::vec2 jitter{0.0f};
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
    // A managed output's descriptor under the current knobs (SSAO's size
    // follows ssao.resolution); by default the declared one.
    virtual ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const {
        (void)knobs;
        return output.resource;
    }
    // Whether a managed output exists under the current knobs: the outputs
    // of an OIT method other than the one oit.method names are not
    // allocated (nor is their memory spent). By default every one.
    virtual bool allocates(const OutputDecl& output, const KnobRegistry& knobs) const {
        (void)output;
        (void)knobs;
        return true;
    }
    // After every pass has declared its knobs: resolve other passes' knobs
    // (KnobRegistry::require*), which throws if one is missing.
    virtual void connect(const KnobRegistry& knobs) { (void)knobs; }
    // Non-empty when the pass cannot or should not run: switched off, or the
    // scene has nothing for it. Shown in the inspector as the skip reason.
    virtual std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const {
        (void)knobs;
        (void)scene;
        return {};
    }
    // Like skipReason, for this frame's view (the pipeline asks after
    // skipReason, with the frame's camera): non-empty when nothing the pass
    // would draw is in view ("model only what the scene requires").
    virtual std::string viewSkipReason(const KnobRegistry& knobs, const Scene& scene, const CameraUniforms& camera) const {
        (void)knobs;
        (void)scene;
        (void)camera;
        return {};
    }
    // Asked of every pass at the start of each frame, with the output size
    // (before the camera is built): the largest scale and the first non-zero
    // jitter apply. A pass that asks for a scale caps it itself (memory) and
    // returns {} unless its knobs choose it.
    virtual FrameSampling sampling(const KnobRegistry& knobs, std::uint64_t frameIndex, int width, int height) {
        (void)knobs;
        (void)frameIndex;
        (void)width;
        (void)height;
        return {};
    }
    // Creates programs and size-independent GL objects. Called once with a context.
    virtual void setup(gl::ShaderLibrary& shaders) = 0;
    // Only for imported outputs (ResourceDesc format 0): (re)creates them and
    // binds them in `outputs`. Managed outputs need nothing here.
    virtual void resize(int width, int height, OutputRegistry& outputs) {
        (void)width;
        (void)height;
        (void)outputs;
    }
    virtual void execute(FrameContext& ctx) = 0;
    // A line for the inspector about the last execution ("36 lights: 30 volumes, 6 culled").
    virtual std::string stats() const { return {}; }
    // A line the user must be told about the last execution, or empty: what
    // it silently got wrong otherwise (the oit pass's lost fragments). The
    // render command prints it, Python warns, the window shows it in Messages.
    virtual std::string frameWarning() const { return {}; }
};

}  // namespace dw
