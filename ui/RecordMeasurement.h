#pragma once
// The window's *Save record* as a measurement (issue 24): the state on show
// when Save was pressed (scene, camera, every knob, the render size, the
// viewport's output) rendered `warmup + frames` times on the stepping
// ConfigurationRunner bench and tradeoff use, one frame a UI frame before
// the view's own (as the Pareto panel's quick sweep runs), so the window
// keeps running; then the experiment record is written with each
// timing series' median and its 95% bootstrap interval, as `render --record
// --frames N` writes one. Knobs or the camera changed meanwhile do not change
// what is measured: each measured frame renders the saved state and puts the
// current one back. Another scene, or another render size (a resize of the
// viewport, a resolution step), stops it with a message: its frames would no
// longer be of one state. The GPU timings' *pause* is lifted while it runs
// (paused, the timer records no sample).
// Defaults: bench's 10 counted frames after 1 warm-up frame, enough for an
// interval (kMinIntervalSamples is 6). Errors: logged (Messages, the banner)
// with the action "save record"; a file that cannot be written keeps nothing.
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "renderer/RenderSession.h"
#include "renderer/bench/ConfigurationRunner.h"
#include "renderer/scene/Camera.h"

namespace dw::ui {

struct UiState;

class RecordMeasurement {
public:
    static constexpr int kDefaultFrames = 10;  // bench's --frames default
    static constexpr int kDefaultWarmup = 1;   // bench's --warmup default

    // Takes the state on show and starts measuring it; false (and the reason
    // logged) when nothing has been rendered yet, a measurement is running,
    // or frames / warm-up are outside render's --frames / --warmup ranges.
    bool start(UiState& state, RenderSession& session, const std::string& path, int frames = kDefaultFrames,
               int warmup = kDefaultWarmup);
    // Renders the next measured frame (the frame loop, once a UI frame); on
    // the last one writes the record. True while frames remain.
    bool step(UiState& state, RenderSession& session);
    // start(), then step() until done: `gui --save-record` at exit.
    bool runNow(UiState& state, RenderSession& session, const std::string& path, int frames = kDefaultFrames,
                int warmup = kDefaultWarmup);
    void cancel(UiState& state, RenderSession& session, const std::string& why = "cancelled");

    bool running() const { return running_; }
    // Frames rendered over frames to render, 0..1.
    double progress() const { return total() ? static_cast<double>(rendered_) / total() : 0.0; }
    int rendered() const { return rendered_; }
    int total() const { return frames_ + warmup_; }
    const std::string& path() const { return path_; }
    // The last measurement's outcome: whether it wrote its record.
    bool wrote() const { return wrote_; }

private:
    void beginRunner(RenderSession& session);
    void finish(UiState& state, RenderSession& session);
    void stop(UiState& state, RenderSession& session);

    bool running_ = false, wrote_ = false;
    bool resumePause_ = false;  // the timer was paused before: paused again after
    std::string path_, shownPath_, buffer_;
    int frames_ = 0, warmup_ = 0, rendered_ = 0;
    std::optional<KnobRegistry> knobs_;
    Camera camera_;
    int width_ = 0, height_ = 0;
    const void* scene_ = nullptr;
    std::string sceneSource_;
    std::unique_ptr<ConfigurationRunner> runner_;  // while measuring
};

}  // namespace dw::ui
