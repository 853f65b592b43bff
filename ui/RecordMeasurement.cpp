#include "ui/RecordMeasurement.h"

#include <algorithm>
#include <filesystem>

#include "renderer/Error.h"
#include "renderer/OptionLimits.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/scene/ClipChoice.h"
#include "renderer/scene/SceneLoader.h"
#include "ui/UiState.h"

namespace dw::ui {

namespace fs = std::filesystem;

namespace {
constexpr const char* kAction = "save record";

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.target == b.target && a.up == b.up && a.fovYDegrees == b.fovYDegrees &&
           a.nearPlane == b.nearPlane && a.farPlane == b.farPlane;
}
bool sameLight(const Light& a, const Light& b) {
    return a.name == b.name && a.type == b.type && a.position == b.position && a.direction == b.direction &&
           a.cutoffDegrees == b.cutoffDegrees && a.exponent == b.exponent && a.falloff == b.falloff &&
           a.innerConeDegrees == b.innerConeDegrees && a.intensity == b.intensity &&
           a.attenuation.constant == b.attenuation.constant && a.attenuation.linear == b.attenuation.linear &&
           a.attenuation.quadratic == b.attenuation.quadratic && a.castShadows == b.castShadows &&
           a.enabled == b.enabled;
}

// A record holds the scene file (its path and hashes), not the window's
// edits of it: what makes the image but cannot be replayed is refused by
// name before any frame (a record of it replayed 'differs' naming nothing).
void requireReplayableScene(const UiState& state, const Scene& scene) {
    if (!scene.flames.empty())
        throw Error("'" + scene.name + "' animates (its flame particles move with the frame index) and replay "
                    "begins at frame 0, as render --frames does: record it with render --record");
    if (state.animator.running())
        throw Error("the lights are animated (Lights > animate): a record holds the scene file's lights; stop the "
                    "animation, put the lights back, then save");
    if (state.timeline.running())
        throw Error("the scene's animation is playing (Scene > animation): a record holds one scene time; pause it, "
                    "then save (the record keeps the time shown)");
    if (scene.source.empty()) return;
    const Scene file = loadScene(scene.source);
    std::string edited;
    size_t count = 0;
    if (file.lights.size() != scene.lights.size()) {
        edited = std::to_string(scene.lights.size()) + " lights where the file has " + std::to_string(file.lights.size());
    } else {
        for (size_t i = 0; i < file.lights.size(); ++i)
            if (!sameLight(file.lights[i], scene.lights[i]) && ++count <= 3)
                edited += (edited.empty() ? "" : ", ") + scene.lights[i].name;
        if (count > 3) edited += " and " + std::to_string(count - 3) + " more";
    }
    if (!edited.empty())
        throw Error("the lights differ from the scene file's (" + edited + ", edited in the Lights panel): a record "
                    "holds the scene file, not edits of it; put them back, or write them into a scene JSON and open "
                    "that, then save");
}
}  // namespace

bool RecordMeasurement::start(UiState& state, RenderSession& session, const std::string& path, int frames, int warmup) {
    std::error_code ec;
    const std::string shown = fs::absolute(path, ec).string();
    try {
        if (running_) throw Error("a record is being measured (" + shownPath_ + "); cancel it first");
        if (path.empty()) throw Error("no file named");
        requireReplayableScene(state, session.scene());
        auto range = [](const OptionRange& r) { return std::to_string(r.min) + ".." + std::to_string(r.max); };
        if (!limits::kFrames.holds(frames))
            throw Error("frames: " + std::to_string(frames) + " is outside --frames's range " + range(limits::kFrames));
        if (!limits::kWarmup.holds(warmup))
            throw Error("warm-up: " + std::to_string(warmup) + " is outside --warmup's range " + range(limits::kWarmup));
        // The output the viewport shows; a preview mode (textured, wireframe)
        // is no pipeline output: final then.
        std::string buffer = state.viewport.mode == DisplayMode::Deferred ? state.viewport.output : "final";
        if (buffer.empty() || !session.pipeline().outputs().find(buffer)) buffer = "final";
        if (!session.pipeline().outputs().find(buffer)) throw Error("no frame rendered yet: nothing to record");
        buffer_ = buffer;
        if (state.viewport.mode != DisplayMode::Deferred)
            state.log.info("the view shows a preview (not a pipeline output): the record holds the deferred 'final'",
                           state.time);
    } catch (const std::exception& e) {
        state.log.error("cannot save record " + shown + ": " + e.what(), state.time, kAction);
        return false;
    }
    path_ = path;
    shownPath_ = shown;
    frames_ = frames;
    warmup_ = warmup;
    rendered_ = 0;
    knobs_ = session.knobs();
    camera_ = session.camera();
    width_ = session.pipeline().width();
    height_ = session.pipeline().height();
    scene_ = &session.scene();
    sceneSource_ = session.scene().source;
    beginRunner(session);
    PassTimer& timer = session.pipeline().timer();
    // Every counted frame's sample kept, with room for the view's frames between them.
    timer.setHistoryLength(std::max(timer.historyLength(), static_cast<size_t>(2 * (frames + warmup) + 64)));
    resumePause_ = timer.paused();
    timer.setPaused(false);  // paused, the counted frames' times would never be recorded
    running_ = true;
    wrote_ = false;
    state.log.info("measuring the record " + shownPath_ + ": " + std::to_string(warmup) + " warm-up and " +
                       std::to_string(frames) + " counted frames of " + buffer_ + " at " + std::to_string(width_) + "x" +
                       std::to_string(height_),
                   state.time);
    return true;
}

bool RecordMeasurement::step(UiState& state, RenderSession& session) {
    if (!running_) return false;
    if (&session.scene() != scene_ || session.scene().source != sceneSource_) {
        cancel(state, session, "stopped: another scene was opened");
        return false;
    }
    if (session.pipeline().width() != width_ || session.pipeline().height() != height_) {
        cancel(state, session,
               "stopped: the view changed size (" + std::to_string(width_) + "x" + std::to_string(height_) + " -> " +
                   std::to_string(session.pipeline().width()) + "x" + std::to_string(session.pipeline().height()) +
                   "), so its frames would not be of one state");
        return false;
    }
    // The saved state for this frame (the runner selects it), the current one put back after it.
    KnobRegistry& knobs = session.knobs();
    const KnobRegistry current = knobs;
    const Camera currentCamera = session.camera();
    try {
        const bool more = runner_->step();
        ++rendered_;
        if (!more) finish(state, session);
    } catch (const std::exception& e) {
        running_ = false;
        state.log.error("cannot save record " + shownPath_ + ": frame " + std::to_string(rendered_ + 1) + " failed: " +
                            e.what(),
                        state.time, kAction);
    }
    const bool differs = knobs.generation() != current.generation() || !sameCamera(currentCamera, camera_);
    knobs.copyValues(current);
    session.camera() = currentCamera;
    // The view shows the pipeline's outputs: after a frame of another state,
    // or one that produced fewer outputs than the view asks for (a buffer
    // alone, no side view, no A/B images), it renders its own again.
    if (differs || buffer_ != "final" || state.panels.sideView || state.ab.enabled) state.forceRender = true;
    if (!running_) stop(state, session);
    return running_;
}

// `render --frames N --warmup W` on the stepping runner bench and tradeoff
// use: one configuration (the saved state, made current before every frame,
// since the view puts its own back between steps), its warm-up frames then
// its counted frames, the viewport's output asked for.
void RecordMeasurement::beginRunner(RenderSession& session) {
    RunnerPlan plan;
    plan.configurations = 1;
    plan.frames = frames_;
    plan.warmup = warmup_;
    plan.block = frames_;
    plan.request = FrameRequest{{buffer_}};
    plan.selectEveryFrame = true;
    runner_ = std::make_unique<ConfigurationRunner>(
        plan,
        [this, &session](int) -> RenderSession& {
            session.knobs().copyValues(*knobs_);
            session.camera() = camera_;
            return session;
        },
        [](RenderSession&, int, int) {});
    const KnobRegistry current = session.knobs();
    runner_->begin("record", {});
    session.knobs().copyValues(current);
}

void RecordMeasurement::finish(UiState& state, RenderSession& session) {
    running_ = false;
    try {
        RunConfig run = state.run;
        run.width = width_;
        run.height = height_;
        run.frames = frames_;
        run.warmup = warmup_;
        run.sceneTime = session.sceneTime();  // the Scene panel's timeline
        run.animation = clipChoiceOf(session.scene().animation);  // and its clip
        const RunnerTimings timings = runner_->finish();
        runner_.reset();
        std::uint64_t first = 0;
        for (const BenchSample& b : timings.samples) first = first == 0 ? b.frame : std::min(first, b.frame);
        ExperimentRecord r = ExperimentRecord::capture(session, run, buffer_, first, "window");
        // Only the measured frames, as the runner harvested them (the view
        // renders frames of its own between them), in pipeline order.
        r.timings.clear();
        for (const BenchSample& b : timings.samples) {
            auto it = std::find_if(r.timings.begin(), r.timings.end(),
                                   [&](const RecordedSeries& rs) { return rs.name == b.series; });
            if (it == r.timings.end()) it = r.timings.insert(r.timings.end(), RecordedSeries{b.series, {}, {}});
            it->gpuMs.push_back(b.gpuMs);
            it->cpuMs.push_back(b.cpuMs);
        }
        r.command = "gui";
        r.sceneSpec = session.scene().source;  // what is open now, not what the window started with
        r.write(path_);
        wrote_ = true;
        size_t timed = 0;
        for (const RecordedSeries& s : r.timings)
            if (s.name == PassTimer::kFrameSeries) timed = s.gpuMs.size();
        std::string note;
        if (timed < static_cast<size_t>(frames_))
            note = "; " + std::to_string(timed) + " of " + std::to_string(frames_) + " frames timed";
        state.log.done("saved record " + shownPath_ + " (" + std::to_string(frames_) + " frames at " +
                           std::to_string(width_) + "x" + std::to_string(height_) + note +
                           "; deferred-workbench replay measures it again)",
                       state.time, kAction);
        state.log.succeeded(kAction);
    } catch (const std::exception& e) {
        state.log.error("cannot save record " + shownPath_ + ": " + e.what(), state.time, kAction);
    }
}

void RecordMeasurement::stop(UiState&, RenderSession& session) {
    running_ = false;
    runner_.reset();
    if (resumePause_) session.pipeline().timer().setPaused(true);
    resumePause_ = false;
    knobs_.reset();
}

void RecordMeasurement::cancel(UiState& state, RenderSession& session, const std::string& why) {
    if (!running_) return;
    stop(state, session);
    const std::string text = "record " + shownPath_ + " not saved: " + why + " after " + std::to_string(rendered_) + " of " +
                             std::to_string(total()) + " frames";
    if (why == "cancelled") state.log.info(text, state.time);
    else state.log.error(text, state.time, kAction);
}

bool RecordMeasurement::runNow(UiState& state, RenderSession& session, const std::string& path, int frames, int warmup) {
    if (!start(state, session, path, frames, warmup)) return false;
    while (step(state, session)) {
    }
    return wrote_;
}

}  // namespace dw::ui
