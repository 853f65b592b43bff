#include "ui/FitBudgetRun.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/Error.h"
#include "renderer/ao/AovCostEstimate.h"
#include "renderer/bench/TradeoffEvidence.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/graph/PassTimer.h"
#include "renderer/metrics/Bootstrap.h"

namespace dw::ui {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The median of a point's per-frame times with its 95% bootstrap interval (NaN: no frame).
void medianOf(const std::map<int, std::map<int, double>>& times, size_t configuration, double& value, double& lo,
              double& hi, int& frames) {
    value = lo = hi = kNaN;
    std::vector<double> v;
    if (const auto it = times.find(static_cast<int>(configuration)); it != times.end())
        for (const auto& [sample, ms] : it->second) v.push_back(ms);
    frames = static_cast<int>(v.size());
    if (v.empty()) return;
    const MedianInterval i = bootstrapMedian(v, 2000, 12345 + configuration);
    value = i.median;
    lo = i.low;
    hi = i.high;
}

}  // namespace

void FitBudgetRun::check(const FitBudgetSettings& s, RenderSession& session) {
    BudgetPicker::check(s.budgetMs);  // as tradeoff --budget-ms refuses it, in its words
    if (s.time == "frame") return;
    std::vector<std::string> terms;
    try {
        terms = TradeoffTable::timeTerms(s.time);
    } catch (const std::exception& e) {
        throw Error("time '" + s.time + "': " + e.what());
    }
    const std::vector<PassInfo> passes = session.pipeline().passList();
    std::string list;
    for (const PassInfo& p : passes) list += (list.empty() ? "" : ", ") + p.name;
    for (const std::string& term : terms) {
        const std::string pass = term.substr(0, term.find('/'));
        if (std::none_of(passes.begin(), passes.end(), [&](const PassInfo& p) { return p.name == pass; }))
            throw Error("time '" + s.time + "': the pipeline has no pass '" + pass + "' (expected frame or one of: " +
                        list + ", or a sum of them: a+b)");
    }
}

void FitBudgetRun::start(RenderSession& session, FloatImage baseline, std::string baselineName,
                         const FitBudgetSettings& settings) {
    check(settings, session);
    settings_ = settings;
    settings_.frames = std::max(settings_.frames, 1);
    settings_.warmup = std::max(settings_.warmup, 0);
    previous_ = std::make_unique<KnobRegistry>(session.knobs());
    camera_ = session.camera();
    sceneSource_ = session.scene().source;
    planPoints(session);
    baseline_ = std::move(baseline);
    baselineName_ = std::move(baselineName);
    errors_.assign(points_.size(), ErrorEstimate{kNaN, kNaN, kNaN, {}});
    runner_.reset();
    session_ = nullptr;
    error_.clear();
    table_ = TradeoffTable{};
    pick_ = BudgetPick{};
    done_ = false;
    running_ = true;
}

// The sweep `tradeoff --knobs speed/quality` makes about these settings, less
// the points the live view's AOV guard would refuse at the view's size.
void FitBudgetRun::planPoints(RenderSession& session) {
    sweep_ = TradeoffSweep::aroundCurrent(*previous_);
    if (sweep_.axes.empty()) throw Error("no knob marked as trading speed for quality has two values to sweep");
    points_.clear();
    leftOut_ = 0;
    const int w = std::max(session.pipeline().width(), 16), h = std::max(session.pipeline().height(), 16);
    for (TradeoffPoint& p : sweep_.points()) {
        KnobRegistry trial = *previous_;
        for (size_t a = 0; a < sweep_.axes.size(); ++a) trial.setFromString(sweep_.axes[a].name, p.values[a]);
        const auto e = AovCostEstimate::forKnobs(trial, session.scene(), session.camera(), w, h);
        if (e) {
            const auto [aw, ah] = AovCostEstimate::aoSize(trial, w, h);
            if (AovCostEstimate::exceeds(*e, aw, ah)) {
                ++leftOut_;
                continue;
            }
        }
        points_.push_back(std::move(p));
    }
    if (points_.empty()) throw Error("every point of the sweep is over the AOV cost limit at this size");
}

std::vector<std::string> FitBudgetRun::assignmentsOf(int point) const {
    for (const TradeoffPoint& p : points_)
        if (p.index == point) {
            std::vector<std::string> out;
            for (size_t a = 0; a < sweep_.axes.size(); ++a) out.push_back(sweep_.axes[a].name + "=" + p.values[a]);
            return out;
        }
    return {};
}

// The timed rounds of bench and tradeoff, one point a configuration: the
// settings the sweep is about with the point's values on top.
void FitBudgetRun::beginRunner(RenderSession& session) {
    session_ = &session;
    RunnerPlan plan;
    plan.configurations = static_cast<int>(points_.size());
    plan.frames = settings_.frames;
    plan.warmup = settings_.warmup;
    plan.block = 1;
    plan.selectEveryFrame = true;  // the view's knobs are put back after every step
    runner_ = std::make_unique<ConfigurationRunner>(
        plan,
        [this](int c) -> RenderSession& {
            KnobRegistry& knobs = session_->knobs();
            knobs.copyValues(*previous_);
            const TradeoffPoint& p = points_[static_cast<size_t>(c)];
            for (size_t a = 0; a < sweep_.axes.size(); ++a) knobs.setFromString(sweep_.axes[a].name, p.values[a]);
            selected_ = c;
            return *session_;
        },
        [](RenderSession&, int, int) {});
    // Taken out of the timer after every round (a stream), not at the end: the
    // view's own frames between the sweep's fill the timer's history too, and
    // the first rounds' samples dropped out of it (4 of 6 frames a point).
    runner_->begin(
        "fit budget", [this](int c) { return "point " + std::to_string(points_[static_cast<size_t>(c)].index); }, {},
        [](const std::vector<BenchSample>&) {});
}

// FLIP of the point's final image against the baseline, from its first frame.
void FitBudgetRun::measureError(RenderSession& session, size_t c) {
    if (!std::isnan(errors_[c].value)) return;
    const FloatImage image = TradeoffRunner::measuredImage(session, "final");
    if (image.width != baseline_.width || image.height != baseline_.height)
        throw Error("the view changed size during the sweep");
    errors_[c] = ImageError::measure(baseline_, image, "flip", false, 2000, 12345 + c);
}

bool FitBudgetRun::step(RenderSession& session) {
    if (!running_) return false;
    if (session_ && session_ != &session) {
        error_ = "the sweep was started on another session";
        running_ = false;
        return false;
    }
    if (!sameView(session)) return false;
    const KnobRegistry saved = session.knobs();
    const Camera savedCamera = session.camera();
    session.camera() = camera_;
    bool more = false;
    try {
        if (!runner_) beginRunner(session);
        selected_ = -1;
        more = runner_->step();
        if (selected_ >= 0) measureError(session, static_cast<size_t>(selected_));
    } catch (const std::exception& e) {
        error_ = (selected_ >= 0 ? "point " + std::to_string(points_[static_cast<size_t>(selected_)].index) + ": "
                                 : std::string()) +
                 e.what();
        running_ = false;
    }
    session.knobs().copyValues(saved);
    session.camera() = savedCamera;
    if (!running_) return false;
    if (!more) {
        try {
            finish();
        } catch (const std::exception& e) {
            error_ = e.what();
            running_ = false;
        }
    }
    return running_;
}

// Another scene or another render size ends the run: its points would no longer be of one view.
bool FitBudgetRun::sameView(RenderSession& session) {
    if (session.scene().source != sceneSource_) error_ = "another scene was opened during the sweep";
    else if (session.pipeline().width() != baseline_.width || session.pipeline().height() != baseline_.height)
        error_ = "the view changed size during the sweep";
    else return true;
    running_ = false;
    return false;
}

double FitBudgetRun::progress() const {
    if (done_) return 1.0;
    return runner_ ? runner_->fractionDone() : 0.0;
}

TradeoffRow FitBudgetRun::rowOf(size_t c, const std::map<int, std::map<int, double>>& ranked,
                                const std::map<int, std::map<int, double>>& frame) const {
    TradeoffRow r;
    r.point = points_[c].index;
    r.axisValues = points_[c].values;
    r.camera = "0";
    r.metric = "flip";
    r.buffer = "final";
    r.error = errors_[c].value;
    r.errorLo = errors_[c].low;
    r.errorHi = errors_[c].high;
    medianOf(frame, c, r.frameGpuMs, r.frameGpuMsLo, r.frameGpuMsHi, r.frames);
    int timed = 0;
    medianOf(ranked, c, r.timeMs, r.timeMsLo, r.timeMsHi, timed);
    return r;
}

// The table (a row a point, its time and error with their intervals), its
// front by the intervals rule, and the budget's pick.
void FitBudgetRun::finish() {
    running_ = false;
    const RunnerTimings timings = runner_->finish();
    runner_.reset();
    const FrameTimes ranked = frameTimes(timings.samples, TradeoffTable::timeTerms(settings_.time));
    const FrameTimes frame = frameTimes(timings.samples, {PassTimer::kFrameSeries});
    table_ = TradeoffTable{};
    for (const TradeoffAxis& a : sweep_.axes) table_.axes.push_back(a.name);
    table_.time = settings_.time;
    for (size_t c = 0; c < points_.size(); ++c) table_.rows.push_back(rowOf(c, ranked, frame));
    table_.markParetoFront(settings_.time);
    pick_ = BudgetPicker::pick(table_, settings_.budgetMs, "0");
    done_ = true;
    ++finished_;
}

}  // namespace dw::ui
