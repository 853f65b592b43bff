#pragma once
// What the Python module's Session is in C++ (the bindings, python/Bindings.h, only convert
// types): one RenderSession over the process's headless EGL context, the run
// configuration it was opened with, and the last frame's report and timings.
// Every call checks that it comes from the thread that made the GL context
// (a context is current on one thread only): another thread gets a
// WrongThreadError, never a call into GL without a current context.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/RunConfig.h"
#include "renderer/bench/BenchRunner.h"
#include "renderer/study/BudgetSearch.h"
#include "renderer/study/TradeoffStudy.h"
#include "renderer/graph/TimingReport.h"
#include "renderer/inspect/PixelProbe.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/reference/ViewReference.h"
#include "renderer/scene/SceneFileKind.h"  // refuseNonSceneFile: a record or preset given as the scene

namespace dw {

// A knob name or value the registry refuses (Python: KnobError, a ValueError).
class KnobError : public Error {
public:
    using Error::Error;
};
// A buffer name the pipeline does not publish (Python: ValueError).
class UnknownBufferError : public Error {
public:
    using Error::Error;
};
// A session used from a thread other than the one that made the GL context.
class WrongThreadError : public Error {
public:
    using Error::Error;
};

// One named output as read back: 8-bit display values (`bytes`) for outputs
// that hold them (what render --out .png writes unchanged), else raw floats
// (what --out .exr writes). Rows top-down, channels interleaved.
struct BufferImage {
    int width = 0, height = 0, channels = 0;
    bool eightBit = false;
    std::vector<std::uint8_t> bytes;
    std::vector<float> floats;
};

struct BufferInfo {
    std::string name, kind, pass, description;
};

// The CPU reference's options, as `reference`'s flags (renderer/reference/ViewReference.h).
using ReferenceOptions = reference::ViewReferenceOptions;


class WorkbenchSession {
public:
    // `presets`: applied in order, a later one winning knob by knob (as
    // repeated --preset); `settings`: "name=value" assignments applied after
    // the scene's settings and the presets (as --set). Throws KnobError for a bad assignment, Error /
    // FileError for a bad preset or scene, GlUnsupportedError without GL 4.5.
    WorkbenchSession(const std::string& scene, int width, int height, const std::vector<std::string>& presets,
                     const std::vector<std::string>& settings);
    // On another thread (a Session dropped there) the GL objects are left
    // alone, not deleted without their context.
    ~WorkbenchSession();
    WorkbenchSession(const WorkbenchSession&) = delete;
    WorkbenchSession& operator=(const WorkbenchSession&) = delete;

    // The knob's value as the registry formats it ("true", "16", "0.02", "reinhard").
    std::string getText(const std::string& name) const;
    const KnobSpec& spec(const std::string& name) const;
    double value(const std::string& name) const;
    // As --set name=text: the registry's parse and checks; throws KnobError.
    void set(const std::string& name, const std::string& text);
    const KnobRegistry& knobs() const;

    std::vector<BufferInfo> buffers() const;
    // Throws what render() would throw for these arguments before any frame:
    // Error for frames or warm-up outside render's ranges, UnknownBufferError.
    void checkRender(const std::string& buffer, int frames, int warmup) const;
    // An output of the `reference` pass (reference.lbuffer, reference.final,
    // reference.ao, compare.error): render() needs the CPU reference of the view for it.
    bool isReferenceOutput(const std::string& buffer) const;
    // The index of the last frame render(..., frames, warmup) renders next.
    std::uint64_t lastFrameOf(int frames, int warmup) const;
    // Renders `warmup` + `frames` frames asking for `buffer`, keeps their
    // timings, and reads `buffer` back from the last one. `reference`: the
    // CPU reference of the view, handed to the `reference` pass for these
    // frames (as the workbench's F9 hands it over), which a reference output
    // needs (Error without it); without one the pass holds none.
    BufferImage render(const std::string& buffer, int frames, int warmup,
                       const reference::ReferenceImages* reference = nullptr);
    // AOV's cost warning for the knobs, scene and camera as they are now at
    // the session's size (AovCostEstimate::check, as render prints it);
    // empty when under the limits or AOV is off. render() does not print it:
    // the module warns (warnings.warn) before it renders.
    std::string aovCostWarning() const;
    // What the last render()'s counted frames measured (empty before one).
    const std::optional<TimingReport>& timings() const { return timings_; }
    // The passes' warnings about the last render()'s last frame ("oit: lost N
    // of M transparent fragments ..."), the lines `render` prints; render() in
    // SessionBindings.cpp raises each as a RuntimeWarning.
    const std::vector<std::string>& frameWarnings() const { return frameWarnings_; }
    ProbeResult probe(int x, int y) const;
    // Writes `buffer` of the last frame as render --out does (.png display, .exr raw).
    void writeBuffer(const std::string& buffer, const std::string& path);
    // Every knob as render --dump-knobs writes them.
    void writeKnobValues(const std::string& path) const;
    // The CPU reference of this view (scene, camera, size, knobs), through
    // the cache; the scene as frame `frame` has it (flame particles move with
    // the frame index), none: as the last frame had it. CPU only, reads the
    // session without changing it: runs on any thread while the owning one waits.
    reference::ReferenceImages reference(const ReferenceOptions& options,
                                         std::optional<std::uint64_t> frame = std::nullopt) const;

    void resize(int width, int height);
    // The scene time (seconds) the scene's glTF animation is posed at, for
    // render() and reference() alike (render --scene-time); posed now.
    void setSceneTime(double seconds);
    double sceneTime() const { return run_.sceneTime; }
    int width() const { return width_; }
    int height() const { return height_; }
    const std::string& sceneName() const;
    const RenderSession& session() const { return *session_; }

    // Throws WrongThreadError unless called on the GL context's thread.
    void requireOwningThread() const;

    // A render record (render --record) of the last render(): its buffer,
    // frames and warm-up, the knobs as they are now. Throws Error before any render().
    ExperimentRecord record();
    // Throws Error when a record of frames beginning at `firstFrame` (none:
    // the next render()'s) could not replay: an animated scene (flame
    // particles move with the frame index) begun at another frame than 0,
    // where replay, as the CLI's render, begins.
    void checkRecordStart(std::optional<std::uint64_t> firstFrame, const std::string& what) const;

    // A bench grid (BenchRunner) on the process's GL context, on its thread,
    // as the record `bench --json` writes; `measured` gets the samples (for bench --csv's file).
    // `costWarning`: where bench's warnings go (AOV's cost, lost fragments: BenchRunner::setWarningSink; stderr when unset).
    static ExperimentRecord benchRecord(BenchOptions options, const std::string& ratioOf, int resamples,
                                        BenchResults* measured = nullptr,
                                        const std::function<void(const std::string&)>& costWarning = {});
    // A tradeoff sweep (TradeoffStudy::measure) on the process's GL context,
    // on its thread (WrongThreadError elsewhere), as tradeoff measures it.
    static TradeoffMeasurement tradeoff(TradeoffRunner& runner, int aoRays, ReferencePixels pixels,
                                        const TradeoffStudyProgress& progress);
    // tradeoff(search=True): BudgetSearch on the process's GL context, from the same thread.
    static BudgetSearchResult search(const BudgetSearchOptions& options, const TradeoffStudyProgress& progress);

private:
    std::thread::id owner_;
    RunConfig run_;
    std::unique_ptr<RenderSession> session_;
    // The ray scene the session's references share (one build for all its cameras).
    std::unique_ptr<reference::RaySceneCache> rayScenes_ = std::make_unique<reference::RaySceneCache>();
    int width_ = 0, height_ = 0;
    bool rendered_ = false;
    std::optional<TimingReport> timings_;
    std::vector<std::string> frameWarnings_;
    struct LastRender {
        std::string buffer;
        int frames = 1, warmup = 0;
        std::uint64_t firstCounted = 0;
        std::vector<std::string> knobs;  // every knob's value as text when it rendered
    };
    std::optional<LastRender> last_;
};

}  // namespace dw
