#pragma once
// Builds each frame from the knobs and the scene (DESIGN.md, "Model only what
// the scene requires"): passes run in the order of seed 002 section 6; a pass
// runs only if something this frame consumes one of its outputs (the final
// image, or a buffer being inspected) and it is not switched off or without
// work. Every pass is timed; the report says which ran and why others did not.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "renderer/graph/FrameContext.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/OutputRegistry.h"
#include "renderer/graph/PassTimer.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/graph/PassCatalog.h"
#include "renderer/graph/ResourcePool.h"

namespace dw {

namespace gl {
class ShaderLibrary;
}

struct PassRecord {
    std::string name;
    bool ran = false;
    std::string reason;  // why it did not run
    std::string stats;   // the pass's own line about what it did
    std::string warning; // the pass's frameWarning(): what it lost this frame, or empty
};

struct FrameReport {
    std::uint64_t frameIndex = 0;
    std::vector<PassRecord> passes;
    const PassRecord* find(const std::string& name) const;
    // The passes' warnings this frame, "pass: line" in pipeline order.
    std::vector<std::string> warnings() const;
};

struct FrameRequest {
    std::vector<std::string> outputs{"final"};
};

// "final" names the display image: the end of the post chain this frame (the
// tone mapper's result, then each Post pass that runs, in order).
inline constexpr const char* kFinalOutput = "final";

// One line of `list passes`: a pass in pipeline order with what it reads and writes.
struct PassInfo {
    std::string name;
    PassStage stage = PassStage::Screen;
    std::vector<std::string> reads, optionalReads, modifies;
    std::vector<OutputDecl> writes;
};

class Pipeline {
public:
    // Declares every pass's knobs and outputs; needs no GL context.
    explicit Pipeline(KnobRegistry& knobs);
    ~Pipeline();

    // The rest need a current GL 4.5 context.
    void setup(gl::ShaderLibrary& shaders);
    void setScene(const Scene& scene);  // uploads; `scene` must outlive its use here
    // The scene set before, posed again (poseScene): its moved vertices and draws re-uploaded.
    void updatePose(const Scene& scene) { gpu_.updatePose(scene); }
    // Skinning and morphing by the GPU's compute dispatch (default) or the
    // CPU pose uploaded (GpuScene::setGpuPosing); kept across setScene.
    void setGpuPosing(bool on) {
        gpuPosing_ = on;
        gpu_.setGpuPosing(on, scene_);
    }
    void resize(int width, int height);
    // Renders one frame. Throws dw::Error if a requested output is unknown or
    // could not be produced (the message says why).
    FrameReport render(const Camera& camera, const FrameRequest& request = {});

    const OutputRegistry& outputs() const { return outputs_; }
    PassTimer& timer() { return timer_; }
    // The index the next render() gives its frame (FrameReport::frameIndex).
    std::uint64_t frameIndex() const { return frame_; }
    const std::vector<std::unique_ptr<RenderPass>>& passes() const { return passes_; }
    RenderPass* findPass(const std::string& name) const;
    template <typename T>
    T* pass() const {
        for (const auto& p : passes_)
            if (auto* t = dynamic_cast<T*>(p.get())) return t;
        return nullptr;
    }
    // The output size (resize()); the last frame rendered its frame-sized
    // resources at renderScale() times it per axis (SSAA: RenderPass::sampling).
    int width() const { return width_; }
    int height() const { return height_; }
    int renderScale() const { return scale_; }
    const CameraUniforms& lastCamera() const { return camera_; }
    // Sets and binds the camera uniforms without rendering a frame: for the
    // views drawn outside the passes (the workbench's forward preview and
    // overlays) when no deferred frame runs.
    void bindCamera(const Camera& camera);
    const GpuScene& gpuScene() const { return gpu_; }
    // View and projection built in double precision, in the given depth convention.
    // `jitter` moves the projection by that many pixels (TAA's sub-pixel offsets).
    static CameraUniforms cameraUniforms(const Camera& camera, int width, int height,
                                         DepthMode depthMode = DepthMode::Reversed, glm::vec2 jitter = glm::vec2(0.0f));
    // The output "final" stands for under the current knobs.
    std::string resolveFinal() const;
    // Plans without executing: which passes would run for `request`, in the
    // order they would run, and (optionally) every output that something consumes.
    std::vector<PassRecord> plan(const FrameRequest& request, std::set<std::string>* wanted = nullptr) const;
    // The passes that read knob `knob` (declared it, or looked it up while
    // being made or connected); "*" when the pipeline itself reads it for
    // every pass (depth.mode). Empty for a knob no pass reads.
    const std::set<std::string>& knobReaders(int knob) const;
    // Every pass in pipeline order under the current knobs (`list passes`).
    std::vector<PassInfo> passList() const;
    PassStage stageOf(const RenderPass& pass) const;
    // The managed resources allocated now (after the last frame): an output
    // whose writer did not run, or that nothing asked for, has none.
    std::vector<ResourceRecord> resources() const { return pool_.list(); }

private:
    struct Plan {
        std::vector<size_t> order;          // pass indices in execution order
        std::vector<PassRecord> records;    // by pass index
        std::vector<std::string> image;     // by pass index: what kCurrentImage is for it
        std::set<std::string> wanted;
        std::string finalName;
    };
    Plan makePlan(const FrameRequest& request) const;
    PassIO resolvedInputs(size_t pass, const Plan& plan) const;
    std::vector<size_t> orderPasses(const std::vector<PassIO>& io) const;
    void allocateResources(const Plan& plan);
    // The bytes of the resources pass `i` reads and writes this frame (its
    // inputs, optional inputs that exist, modified resources and outputs, each
    // once; a mip view counts in its texture): PassCounts::Bytes.
    std::int64_t declaredBytes(size_t i, const Plan& plan) const;

    KnobRegistry& knobs_;
    std::vector<std::unique_ptr<RenderPass>> passes_;
    std::vector<PassStage> stages_;
    ResourcePool pool_;
    OutputRegistry outputs_;
    PassTimer timer_;
    GpuScene gpu_;
    gl::ParamBuffer<gpu::CameraBlock> cameraUbo_;
    gl::ShaderLibrary* shaders_ = nullptr;
    const Scene* scene_ = nullptr;
    CameraUniforms camera_;
    bool viewKnown_ = false;  // camera_ holds a frame's camera (passes may skip by view)
    EnumKnob depthMode_;  // depth.mode: 0 reversed, 1 conventional
    bool gpuPosing_ = true;
    EnumKnob normalEncoding_;  // gbuffer.normal_encoding: kl16, oct16, oct8
    int octahedral_[2] = {-1, -1};  // its octahedral choices
    // CameraBlock::gbuffer.x: 0 Kircher-Lawrance, 1 octahedral.
    float normalEncodingUniform() const;
    int width_ = 0, height_ = 0;
    int scale_ = 1;  // this frame's render scale (FrameSampling::scale)
    glm::vec2 jitter_{0.0f};  // this frame's projection jitter in pixels
    // Asks every pass how to sample this frame (RenderPass::sampling).
    void chooseSampling();
    int renderWidth() const { return width_ * scale_; }
    int renderHeight() const { return height_ * scale_; }
    std::uint64_t frame_ = 0;
    std::vector<std::set<std::string>> knobReaders_;  // by knob id
};

}  // namespace dw
