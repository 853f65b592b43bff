#pragma once
// The measuring loop `bench` and `tradeoff` share: a list of configurations
// (whatever a caller makes them: a size, a light count, knob values, a
// preset, a camera) timed in one process with the same protocol.
//   Interleaving: round after round, every configuration renders its warm-up
//     frames (left out, after every switch to it) and then a block of counted
//     frames, so slow drift of the machine falls on all of them alike.
//   Timestamps: PassTimer's GL_TIMESTAMP pairs, harvested without waiting
//     while the loop runs and with one wait at the end, never inside a frame.
//   Time left: from each configuration's own measured wall time per frame
//     (the configurations not yet reached at the mean of those measured).
// It reads: the sessions `select` returns; writes: BenchSamples in pipeline
// order (per configuration, then sample, then pass, its spans, "frame" last).
// Follows seed 000 chapter 6's measurement (several frames per strategy,
// medians) with the interleaving and warm-up made explicit.
// The bootstrap intervals are computed from the samples (Bootstrap.h).
// Also renders untimed frames of a configuration (capture) for images and
// counts. Needs a current GL 4.5 context for measure/capture.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/bench/BenchResults.h"

namespace dw {

struct RunnerPlan {
    int configurations = 0;
    int frames = 10;  // counted frames per configuration
    int warmup = 1;   // left out after each switch to a configuration
    int block = 1;    // counted frames per configuration in a row
    // What every frame asks for (FrameRequest::outputs): by default the final
    // image, as a user would see it; a record of another buffer asks for it.
    FrameRequest request;
    // Select the configuration before every frame, not once a block: for a
    // caller whose own loop changes the session between steps (the window's
    // quick sweep and records put the view's state back after each frame).
    bool selectEveryFrame = false;
    // Count each pass's cost counters (PassTimer::setCounting) in every
    // session it renders with; BenchSample::counts carries them.
    bool counters = false;
};

// What the passes said they lost in a configuration's counted frames
// (FrameReport::warnings: the oit pass's lost fragments): a measurement of a
// configuration that drops fragments is not the method's cost or error, and
// bench and tradeoff say so as render does.
struct FrameWarnings {
    int frames = 0;                   // counted frames with any warning
    std::vector<std::string> first;   // the first such frame's warnings
    // "oit: lost N of M ... (in K of F counted frames; the first such frame's figures)".
    std::string text(int countedFrames) const;
};

struct RunnerTimings {
    std::vector<BenchSample> samples;  // BenchSample::config = the runner's configuration number
    // The configurations whose counted frames warned (none: not listed).
    std::map<int, FrameWarnings> warnings;
    // Each pass's statistics line (PassRecord::stats) of each configuration's last counted frame.
    std::map<int, std::map<std::string, std::string>> stats;
    // Each configuration's peak GPU memory over its counted frames, in bytes:
    // the largest its session's pipeline held (gl/MemoryDomain.h; logical
    // bytes, gl/MemoryLedger.h), the peak started afresh before each counted
    // frame, so what an earlier configuration's frame graph held is given
    // back by the warm-up frame after a switch. Exact: the same run gives the same.
    std::map<int, std::size_t> memoryPeak;
    double seconds = 0.0;
};

class ConfigurationRunner {
public:
    // Makes configuration `config` current (knobs, lights, size, camera
    // settings) and returns the session that renders it. Called on every
    // switch; may return the same session for several configurations.
    using Select = std::function<RenderSession&(int config)>;
    // Places the camera for counted frame `sample` (0..frames-1) of `config`;
    // warm-up frames use their block's first sample.
    using Pose = std::function<void(RenderSession&, int config, int sample)>;
    using Progress = std::function<void(const std::string&)>;
    // Called after each round with the samples of the frames harvested so far
    // that were not handed out before (whole frames; configuration order not
    // guaranteed): lets a caller stream them to a file.
    using Stream = std::function<void(const std::vector<BenchSample>&)>;

    ConfigurationRunner(RunnerPlan plan, Select select, Pose pose);

    const RunnerPlan& plan() const { return plan_; }
    // Counted frames are interleaved in rounds of `block` frames.
    int rounds() const { return (plan_.frames + plan_.block - 1) / plan_.block; }

    // The timed rounds. `name` opens the progress lines ("bench", "tradeoff");
    // `describe(config)` says which configuration is running. `skip(config,
    // sample)` true leaves a counted frame out (already measured: a resumed run).
    // The same as begin(), step() until it returns false, then finish().
    RunnerTimings measure(const std::string& name, const std::function<std::string(int)>& describe,
                          const Progress& progress = {}, const Stream& stream = {},
                          const std::function<bool(int, int)>& skip = {});

    // The timed rounds a frame at a time, for a caller with a loop of its
    // own (a window draws between steps): begin() plans (measure's
    // arguments), each step() renders one frame (a configuration's block of a
    // round is its warm-up frames after a switch, then its counted frames;
    // samples streamed after each round; RunnerPlan::selectEveryFrame makes
    // the configuration current before every frame) and returns whether another frame remains;
    // finish() waits for the last timestamps and returns what measure()
    // returns. Throws dw::Error when step() or finish() come before begin().
    void begin(const std::string& name, const std::function<std::string(int)>& describe,
               const Progress& progress = {}, const Stream& stream = {},
               const std::function<bool(int, int)>& skip = {});
    bool step();
    RunnerTimings finish();
    // Counted frames rendered over the frames to render (0 before begin()).
    double fractionDone() const;

    // Seconds left: each configuration's measured wall seconds per round
    // (negative: not measured yet) times its rounds left; the ones not
    // measured yet at the mean of those measured (0 when none is).
    static double timeLeft(const std::vector<double>& roundSeconds, const std::vector<int>& roundsLeft);

    // One untimed frame of `config` at counted frame `sample`'s pose, asking
    // for `request`'s outputs; returns the session to read them from.
    RenderSession& capture(int config, int sample, const FrameRequest& request);

    ~ConfigurationRunner();
    ConfigurationRunner(ConfigurationRunner&&) noexcept;
    ConfigurationRunner& operator=(ConfigurationRunner&&) noexcept;

private:
    struct Measurement;
    void planBlock();
    void renderFrame();
    void endBlock();
    void endRound();
    void sayProgress(int round, int config);

    RunnerPlan plan_;
    Select select_;
    Pose pose_;
    std::unique_ptr<Measurement> m_;  // between begin() and finish()
};

}  // namespace dw
