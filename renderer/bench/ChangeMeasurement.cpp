#include "renderer/bench/ChangeMeasurement.h"

#include <algorithm>
#include <map>
#include <vector>

#include "renderer/Error.h"

namespace dw {

ChangeMeasurement::ChangeMeasurement() = default;
ChangeMeasurement::~ChangeMeasurement() = default;
ChangeMeasurement::ChangeMeasurement(ChangeMeasurement&&) noexcept = default;
ChangeMeasurement& ChangeMeasurement::operator=(ChangeMeasurement&&) noexcept = default;

RunnerPlan ChangeMeasurement::planOf(const Settings& s) {
    RunnerPlan plan;
    plan.configurations = 2;
    plan.frames = std::clamp(s.framesPerSide, 2, 150);
    plan.warmup = std::max(s.settle, 0);
    plan.block = std::max(s.perTurn, 1);
    plan.selectEveryFrame = true;  // the view puts the after values back between steps
    return plan;
}

void ChangeMeasurement::start(const KnobChange& change, const Settings& settings, std::set<std::string> influenced) {
    *this = ChangeMeasurement();
    change_ = change;
    settings_ = settings;
    settings_.framesPerSide = std::clamp(settings_.framesPerSide, 2, 150);
    influenced_ = std::move(influenced);
    const RunnerPlan plan = planOf(settings_);
    const int rounds = (plan.frames + plan.block - 1) / plan.block;
    scheduled_ = plan.configurations * (rounds * plan.warmup + plan.frames);
    state_ = change_.empty() ? State::Idle : State::Rendering;
}

void ChangeMeasurement::setSide(KnobRegistry& knobs, bool after) {
    lastSet_.clear();
    for (size_t i = 0; i < change_.knobs.size(); ++i) {
        knobs.set(change_.knobs[i], after ? change_.after[i] : change_.before[i]);
        lastSet_.push_back(knobs.value(change_.knobs[i]));
    }
}

void ChangeMeasurement::restore(KnobRegistry& knobs) {
    for (size_t i = 0; i < change_.knobs.size(); ++i)
        if (i >= lastSet_.size() || knobs.value(change_.knobs[i]) == lastSet_[i]) knobs.set(change_.knobs[i], change_.after[i]);
    lastSet_.clear();
}

void ChangeMeasurement::cancel(KnobRegistry& knobs, const std::string& why) {
    if (!active()) return;
    restore(knobs);
    runner_.reset();
    state_ = State::Cancelled;
    why_ = why;
}

bool ChangeMeasurement::step(RenderSession& session) {
    if (state_ != State::Rendering) return false;
    KnobRegistry& knobs = session.knobs();
    if (session_ && session_ != &session) {
        cancel(knobs, "cancelled: the measurement was started on another session");
        return false;
    }
    if (restored_ && knobs.generation() != generation_) {
        cancel(knobs, "cancelled: a knob changed during the measurement");
        return false;
    }
    bool more = false;
    try {
        if (!runner_) {
            session_ = &session;
            runner_ = std::make_unique<ConfigurationRunner>(
                planOf(settings_),
                [this](int side) -> RenderSession& {
                    setSide(session_->knobs(), side == 1);
                    return *session_;
                },
                [](RenderSession&, int, int) {});
            runner_->begin("cost of a change", [](int side) { return side == 1 ? "after" : "before"; });
        }
        more = runner_->step();
        ++rendered_;
    } catch (const std::exception& e) {
        cancel(knobs, std::string("cancelled: ") + e.what());
        return false;
    }
    restore(knobs);
    generation_ = knobs.generation();
    restored_ = true;
    if (!more) finish();
    return active();
}

// The runner's samples per side (waiting for the last GPU times), judged in
// pipeline order.
void ChangeMeasurement::finish() {
    const RunnerTimings timings = runner_->finish();
    runner_.reset();
    SeriesSamples before, after;
    std::vector<std::string> order;
    for (const BenchSample& s : timings.samples) {
        (s.config == 1 ? after : before)[s.series].push_back(s.gpuMs);
        if (std::find(order.begin(), order.end(), s.series) == order.end()) order.push_back(s.series);
    }
    verdict_ = judgeChange(before, after, influenced_, order);
    state_ = State::Done;
}

float ChangeMeasurement::progress() const {
    if (state_ == State::Done) return 1.0f;
    if (scheduled_ <= 0) return 0.0f;
    return static_cast<float>(rendered_) / static_cast<float>(scheduled_);
}

const char* ChangeMeasurement::stateName() const {
    switch (state_) {
        case State::Idle: return "idle";
        case State::Rendering: return "measuring";
        case State::Done: return "done";
        case State::Cancelled: return "cancelled";
    }
    return "";
}

std::string ChangeMeasurement::status() const {
    switch (state_) {
        case State::Idle: return "not measured";
        case State::Rendering:
            return "measuring: frame " + std::to_string(rendered_ + 1) + " of " + std::to_string(scheduled_);
        case State::Done: return "done";
        case State::Cancelled: return why_;
    }
    return "";
}

}  // namespace dw
