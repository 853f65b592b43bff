#include "renderer/bench/QuickSweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

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

// The median's 95% percentile-bootstrap interval (seeded).
std::pair<double, double> medianInterval(const std::vector<double>& v) {
    if (v.size() < 2) return {kNaN, kNaN};
    std::mt19937_64 rng(12345);
    std::vector<double> r(v.size()), medians;
    for (int i = 0; i < 1000; ++i) {
        for (auto& x : r) x = v[static_cast<size_t>(rng() % v.size())];
        medians.push_back(median(r));
    }
    std::sort(medians.begin(), medians.end());
    return {medians[25], medians[974]};
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
    total_ = static_cast<int>(values_.size()) * framesPerValue_;
    next_ = 0;
    flip_.assign(values_.size(), kNaN);
    frameValue_.clear();
    error_.clear();
    table_ = TradeoffTable{};
    done_ = false;
    running_ = !values_.empty();
}

bool QuickSweep::step(RenderSession& session) {
    if (!running_) return false;
    KnobRegistry& knobs = session.knobs();
    const int id = *knobs.find(knob_);
    const double saved = knobs.value(id);
    // Round-robin: every value once, then every value again.
    const size_t v = static_cast<size_t>(next_) % values_.size();
    try {
        knobs.setFromString(knob_, values_[v]);
        const FrameReport r = session.pipeline().render(session.camera(), FrameRequest{{"final"}});
        frameValue_[r.frameIndex] = v;
        if (std::isnan(flip_[v])) {
            const FloatImage image = session.readRaw("final");
            if (image.width != baseline_.width || image.height != baseline_.height)
                throw Error("the view changed size during the sweep");
            const ImageComparison c = ImageComparison::measure(baseline_, image, ComparisonSettings{}, baselineName_, values_[v]);
            flip_[v] = c.flip ? c.flip->mean : kNaN;
        }
    } catch (const std::exception& e) {
        error_ = knob_ + "=" + values_[v] + ": " + e.what();
        running_ = false;
    }
    knobs.set(id, saved);
    if (!running_) return false;
    if (++next_ >= total_) finish(session);
    return running_;
}

void QuickSweep::finish(RenderSession& session) {
    running_ = false;
    PassTimer& timer = session.pipeline().timer();
    timer.collect(true);
    std::vector<std::vector<double>> ms(values_.size());
    if (const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries))
        for (const auto& s : total->samples)
            if (const auto it = frameValue_.find(s.frame); it != frameValue_.end()) ms[it->second].push_back(s.gpuMs);
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
        r.frameGpuMs = ms[i].empty() ? kNaN : median(ms[i]);
        std::tie(r.frameGpuMsLo, r.frameGpuMsHi) = medianInterval(ms[i]);
        table_.rows.push_back(r);
    }
    table_.markParetoFront();
    done_ = true;
}

}  // namespace dw
