#pragma once
// What one rendering session holds, wired together: shader library, knobs,
// pipeline, scene and camera. The CLI, the GUI and the tests each build one;
// the session only composes the parts, each of which does its own job.
#include <memory>
#include <string>

#include "renderer/inspect/BufferView.h"
#include "renderer/io/ImageIO.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/RunConfig.h"
#include "renderer/gl/DebugOutput.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace reference {
struct ReferenceImages;
}

class RenderSession {
public:
    // Needs a current GL 4.5 context; throws GlUnsupportedError otherwise.
    explicit RenderSession(const std::filesystem::path& shaderRoot = gl::ShaderLibrary::locateRoot());

    // Loads a built-in scene, scene JSON or glTF. Knobs and camera start as
    // `run` says (RunConfig: defaults, the scene's settings, the preset, --set;
    // the preset's camera on its own scene; the scene time, sceneTime(), at
    // which the scene is posed): every load starts from the defaults, so
    // nothing carries over from the scene before. If anything throws, the
    // previous scene, knobs and camera stay.
    void loadScene(const std::string& spec, const RunConfig& run = {});
    void setScene(Scene scene, const RunConfig& run = {});
    void resize(int width, int height) { pipeline_.resize(width, height); }
    // Moves the scene's flame particles (if any) to the frame's index first,
    // and poses its animation (skins, morph targets, clips) at sceneTime().
    FrameReport render(const FrameRequest& request = {});
    // The scene time the frames are rendered at (seconds; --scene-time):
    // the glTF animation is evaluated there (clamped to each clip's range).
    void setSceneTime(double seconds) { sceneTime_ = seconds; }
    double sceneTime() const { return sceneTime_; }
    // Poses the scene at sceneTime() now (render() does it too): for readers
    // of scene() before the next frame, such as the CPU reference.
    void poseAtSceneTime();

    // A named output as raw floats (for .exr) or as the buffer view shows it
    // (.png); any kind, laid out as the buffer view lays it out (the layer and
    // sample of `selection` / `settings`: by default every layer, resolved).
    FloatImage readRaw(const std::string& output, ViewSelection selection = {}) const;
    FloatImage readDisplay(const std::string& output, BufferViewSettings settings = {});
    // Writes `output` as rendered by the last frame to `path`; .exr raw, .png display.
    void writeOutput(const std::string& output, const std::string& path, const BufferViewSettings& settings = {});
    // Every knob as "name=value" (what --set takes back), after a "# scene
    // <source>" line; what --dump-knobs writes. Throws FileError.
    void writeKnobValues(const std::string& path) const;

    // Hands `images` (a CPU reference of this view, reference/ViewReference)
    // to the `reference` pass for the frames rendered next (what the
    // workbench's F9 hands it): reference.lbuffer, reference.final,
    // reference.ao and compare.error then show it. nullptr takes an earlier
    // one away, with `staleReason` as the pass's skip reason. No effect on a
    // pipeline without the pass.
    void showReference(const reference::ReferenceImages* images, const std::string& staleReason = {});
    // Whether `buffer` is an output of the `reference` pass (reference.lbuffer,
    // reference.final, reference.ao, compare.error): a frame needs the view's
    // reference handed over to produce it.
    bool isReferenceOutput(const std::string& buffer) const;

    KnobRegistry& knobs() { return knobs_; }
    const KnobRegistry& knobs() const { return knobs_; }
    Pipeline& pipeline() { return pipeline_; }
    gl::ShaderLibrary& shaders() { return shaders_; }
    BufferView& bufferView() { return view_; }
    const Scene& scene() const { return *scene_; }
    Scene& mutableScene() { return *scene_; }
    Camera& camera() { return camera_; }
    const gl::GlInfo& glInfo() const { return info_; }

private:
    gl::GlInfo info_;
    gl::ShaderLibrary shaders_;
    KnobRegistry knobs_;
    Pipeline pipeline_;
    BufferView view_;
    std::unique_ptr<Scene> scene_;
    Camera camera_;
    double sceneTime_ = 0.0;
};

}  // namespace dw
