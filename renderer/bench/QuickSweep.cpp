#include "renderer/bench/QuickSweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "renderer/Error.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/metrics/ImageComparison.h"

namespace dw {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string number(double v, bool integer) {
    if (integer) return std::to_string(static_cast<long long>(std::llround(v)));
    char t[32];
    std::snprintf(t, sizeof(t), "%.6g", v);
    return t;
}

}  // namespace

std::vector<std::string> QuickSweep::valuesOf(const KnobRegistry& knobs, const std::string& knob) {
    const auto id = knobs.find(knob);
    if (!id) throw Error("quick sweep: no knob '" + knob + "'");
    const KnobSpec& s = knobs.spec(*id);
    std::vector<std::string> v;
    switch (s.type) {
        case KnobType::Enum: return s.choices;
        case KnobType::Bool: return {"false", "true"};
        case KnobType::Int:
        case KnobType::Float: {
            const bool integer = s.type == KnobType::Int;
            const bool geometric = s.logarithmic && s.minValue > 0.0;
            const int n = integer ? static_cast<int>(std::min(5.0, s.maxValue - s.minValue + 1.0)) : 5;
            for (int i = 0; i < n; ++i) {
                const double t = n > 1 ? static_cast<double>(i) / (n - 1) : 0.0;
                const double x = geometric ? s.minValue * std::pow(s.maxValue / s.minValue, t)
                                           : s.minValue + t * (s.maxValue - s.minValue);
                const std::string text = number(x, integer);
                if (std::find(v.begin(), v.end(), text) == v.end()) v.push_back(text);
            }
            return v;
        }
    }
    return v;
}

void QuickSweep::start(const KnobRegistry& knobs, const std::string& knob, FloatImage baseline, std::string baselineName,
                       int framesPerValue) {
    values_ = valuesOf(knobs, knob);
    knob_ = knob;
    baseline_ = std::move(baseline);
    baselineName_ = std::move(baselineName);
    framesPerValue_ = std::max(framesPerValue, 1);
    runner_.reset();
    session_ = nullptr;
    flip_.assign(values_.size(), kNaN);
    error_.clear();
    table_ = TradeoffTable{};
    done_ = false;
    running_ = !values_.empty();
}

// The timed rounds of bench and tradeoff (ConfigurationRunner), one value a
// configuration: every value a frame in turn, a warm-up frame after each
// switch, the camera as the session holds it.
void QuickSweep::beginRunner(RenderSession& session) {
    session_ = &session;
    RunnerPlan plan;
    plan.configurations = static_cast<int>(values_.size());
    plan.frames = framesPerValue_;
    plan.warmup = 1;
    plan.block = 1;
    plan.selectEveryFrame = true;  // the knob is put back after every step
    runner_ = std::make_unique<ConfigurationRunner>(
        plan,
        [this](int v) -> RenderSession& {
            session_->knobs().setFromString(knob_, values_[static_cast<size_t>(v)]);
            selected_ = v;
            return *session_;
        },
        [](RenderSession&, int, int) {});
    runner_->begin("quick sweep", [this](int v) { return knob_ + "=" + values_[static_cast<size_t>(v)]; });
}

// FLIP of the value's image against the baseline, from its first counted frame.
void QuickSweep::measureFlip(RenderSession& session, size_t v) {
    if (!std::isnan(flip_[v])) return;
    const FloatImage image = session.readRaw("final");
    if (image.width != baseline_.width || image.height != baseline_.height)
        throw Error("the view changed size during the sweep");
    const ImageComparison c = ImageComparison::measure(baseline_, image, ComparisonSettings{}, baselineName_, values_[v]);
    flip_[v] = c.flip ? c.flip->mean : kNaN;
}

bool QuickSweep::step(RenderSession& session) {
    if (!running_) return false;
    if (session_ && session_ != &session) {
        error_ = "the quick sweep of " + knob_ + " was started on another session";
        running_ = false;
        return false;
    }
    KnobRegistry& knobs = session.knobs();
    const int id = *knobs.find(knob_);
    const double saved = knobs.value(id);
    bool more = false;
    try {
        if (!runner_) beginRunner(session);
        selected_ = -1;
        more = runner_->step();
        if (selected_ >= 0) measureFlip(session, static_cast<size_t>(selected_));
    } catch (const std::exception& e) {
        error_ = knob_ + (selected_ >= 0 ? "=" + values_[static_cast<size_t>(selected_)] : std::string()) + ": " + e.what();
        running_ = false;
    }
    knobs.set(id, saved);
    if (!running_) return false;
    if (!more) finish();
    return running_;
}

double QuickSweep::progress() const {
    if (done_) return 1.0;
    return runner_ ? runner_->fractionDone() : 0.0;
}

void QuickSweep::finish() {
    running_ = false;
    const RunnerTimings timings = runner_->finish();
    std::vector<std::vector<double>> ms(values_.size());
    for (const auto& s : timings.samples)
        if (s.series == PassTimer::kFrameSeries) ms[static_cast<size_t>(s.config)].push_back(s.gpuMs);
    table_.axes = {knob_};
    for (size_t i = 0; i < values_.size(); ++i) {
        TradeoffRow r;
        r.point = static_cast<int>(i);
        r.axisValues = {values_[i]};
        r.camera = "0";
        r.metric = "flip";
        r.buffer = "final";
        r.error = flip_[i];
        r.errorLo = r.errorHi = kNaN;
        r.frames = static_cast<int>(ms[i].size());
        r.frameGpuMs = r.frameGpuMsLo = r.frameGpuMsHi = kNaN;
        if (!ms[i].empty()) r.frameGpuMs = median(ms[i]);
        if (ms[i].size() >= 2) {
            const MedianInterval m = bootstrapMedian(ms[i], 2000, 12345 + i);
            r.frameGpuMsLo = m.low;
            r.frameGpuMsHi = m.high;
        }
        table_.rows.push_back(r);
    }
    table_.markParetoFront();
    done_ = true;
}

}  // namespace dw
