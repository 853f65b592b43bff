#pragma once
// One measurement of what a committed knob change costs (the workbench's GPU
// timings panel, graph/ChangeCost's KnobChange and verdict), on the stepping
// ConfigurationRunner bench and tradeoff use: two configurations, the values
// before the change (0) and after it (1), interleaved in turns of `perTurn`
// counted frames with `settle` frames left out after each switch (the
// runner's warm-up: re-created resources and recompiled shaders are not
// counted), until each side has `framesPerSide`. One frame a step, a step a
// UI frame, so the window stays responsive: each step sets the changed knobs
// to its side's values, renders, and puts the after values back; the view
// renders its own frame after it. When the last frame is in, the runner's
// samples per side are judged (judgeChange: medians, the ratio's bootstrap
// interval, Bonferroni over the passes the change can reach).
// A knob changed by anything else between steps cancels the measurement
// (the changed knobs go back to their after values); so does a step on
// another session. Needs a current GL context (the session's).
#include <memory>
#include <set>
#include <string>

#include "renderer/RenderSession.h"
#include "renderer/bench/ConfigurationRunner.h"
#include "renderer/graph/ChangeCost.h"

namespace dw {

class ChangeMeasurement {
public:
    struct Settings {
        int framesPerSide = 12;  // counted frames of each side (2 .. 150)
        int perTurn = 2;         // counted frames per turn (the runner's block)
        int settle = 1;          // frames left out after each switch (the runner's warm-up)
    };
    enum class State { Idle, Rendering, Done, Cancelled };

    // The runner's plan for `settings`: configuration 0 the values before the
    // change, 1 those after; every block a switch, so each has its warm-up.
    static RunnerPlan planOf(const Settings& settings);

    void start(const KnobChange& change, const Settings& settings, std::set<std::string> influenced);
    // Stops; the changed knobs go back to their after values (those the user
    // has not touched since).
    void cancel(KnobRegistry& knobs, const std::string& why = "cancelled");
    // Renders the next measured frame on `session` (the first step's); on the
    // last, waits for its GPU times and judges. True while frames remain.
    bool step(RenderSession& session);

    State state() const { return state_; }
    bool active() const { return state_ == State::Rendering; }
    const KnobChange& change() const { return change_; }
    const Settings& settings() const { return settings_; }
    const ChangeVerdict& verdict() const { return verdict_; }
    const std::set<std::string>& influenced() const { return influenced_; }
    int framesRendered() const { return rendered_; }
    int framesScheduled() const { return scheduled_; }
    float progress() const;
    // "measuring: frame 7 of 36", "done", "cancelled: ..."
    std::string status() const;
    const char* stateName() const;

    ChangeMeasurement();
    ~ChangeMeasurement();
    ChangeMeasurement(ChangeMeasurement&&) noexcept;
    ChangeMeasurement& operator=(ChangeMeasurement&&) noexcept;

private:
    void setSide(KnobRegistry& knobs, bool after);
    void restore(KnobRegistry& knobs);
    void finish();

    State state_ = State::Idle;
    KnobChange change_;
    Settings settings_;
    std::set<std::string> influenced_;
    std::unique_ptr<ConfigurationRunner> runner_;
    RenderSession* session_ = nullptr;  // the session the first step was given
    int rendered_ = 0, scheduled_ = 0;
    std::uint64_t generation_ = 0;  // the registry's generation after our last restore
    bool restored_ = false;         // generation_ holds (a frame was measured)
    std::vector<double> lastSet_;   // the values we set last
    std::string why_;
    ChangeVerdict verdict_;
};

}  // namespace dw
