#include "renderer/graph/ChangeCost.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/graph/Pipeline.h"

namespace dw {

// ---- the committed change ----

void KnobChangeWatcher::reset(const KnobRegistry& knobs) {
    committed_.clear();
    for (size_t i = 0; i < knobs.size(); ++i) committed_.push_back(knobs.value(static_cast<int>(i)));
    generation_ = knobs.generation();
}

std::optional<KnobChange> KnobChangeWatcher::update(const KnobRegistry& knobs, bool editing) {
    if (committed_.size() != knobs.size()) {
        reset(knobs);
        return std::nullopt;
    }
    if (editing || knobs.generation() == generation_) return std::nullopt;
    KnobChange c;
    for (size_t i = 0; i < knobs.size(); ++i) {
        const int id = static_cast<int>(i);
        const double now = knobs.value(id);
        if (now == committed_[i]) continue;
        if (c.knobs.empty())
            c.what = knobs.spec(id).name + " " + knobs.formatValue(id, committed_[i]) + " -> " + knobs.format(id);
        c.knobs.push_back(id);
        c.before.push_back(committed_[i]);
        c.after.push_back(now);
    }
    if (c.knobs.size() > 1) c.what += " and " + std::to_string(c.knobs.size() - 1) + " more";
    reset(knobs);
    if (c.empty()) return std::nullopt;  // typed back the value it had
    return c;
}

// ---- what a change can reach ----

std::set<std::string> influencedPasses(const std::vector<PassEdges>& passes, const std::set<std::string>& readers) {
    std::set<std::string> out;
    const bool all = readers.count("*") > 0;
    std::set<std::string> dirty;  // resources an influenced pass writes
    for (const PassEdges& p : passes) {
        bool hit = all || readers.count(p.name) > 0;
        for (const auto& r : p.reads) hit = hit || dirty.count(r) > 0;
        if (!hit) continue;
        out.insert(p.name);
        dirty.insert(p.writes.begin(), p.writes.end());
    }
    return out;
}

bool seriesInfluenced(const std::string& series, const std::set<std::string>& influenced) {
    if (series == PassTimer::kFrameSeries) return !influenced.empty();
    return influenced.count(series.substr(0, series.find('/'))) > 0;
}

std::vector<PassEdges> passEdges(const Pipeline& pipeline) {
    std::vector<PassEdges> edges;
    for (const PassInfo& p : pipeline.passList()) {
        PassEdges e{p.name, p.reads, {}};
        e.reads.insert(e.reads.end(), p.optionalReads.begin(), p.optionalReads.end());
        e.reads.insert(e.reads.end(), p.modifies.begin(), p.modifies.end());
        for (const auto& o : p.writes) e.writes.push_back(o.name);
        e.writes.insert(e.writes.end(), p.modifies.begin(), p.modifies.end());
        edges.push_back(std::move(e));
    }
    return edges;
}

std::set<std::string> passesReachedBy(const Pipeline& pipeline, const std::vector<int>& knobs) {
    std::set<std::string> readers;
    for (int id : knobs) {
        const std::set<std::string>& r = pipeline.knobReaders(id);
        if (r.empty()) readers.insert("*");  // read by no pass we know of: assume every pass
        readers.insert(r.begin(), r.end());
    }
    return influencedPasses(passEdges(pipeline), readers);
}

// ---- the verdict ----

std::string PassVerdict::describe() const {
    char buf[200];
    if (beforeFrames == 0 && afterFrames > 0) {
        std::snprintf(buf, sizeof(buf), "new: %.3f ms", afterMs);
        return buf;
    }
    if (afterFrames == 0 && beforeFrames > 0) {
        std::snprintf(buf, sizeof(buf), "gone (was %.3f ms)", beforeMs);
        return buf;
    }
    if (!ratio.valid()) return "no data";
    const double diff = afterMs - beforeMs;
    std::snprintf(buf, sizeof(buf), "%+.*f ms (%+.0f%%, %.3g%% CI %+.0f%% to %+.0f%%)", std::fabs(diff) < 1.0 ? 3 : 1, diff,
                  (ratio.ratio - 1.0) * 100.0, confidence * 100.0, (ratio.low - 1.0) * 100.0, (ratio.high - 1.0) * 100.0);
    return buf;
}

const PassVerdict* ChangeVerdict::find(const std::string& pass) const {
    for (const auto& p : passes)
        if (p.pass == pass) return &p;
    return nullptr;
}

std::string ChangeVerdict::method() const {
    char buf[320];
    std::snprintf(buf, sizeof(buf),
                  "%.3g%% interval per pass (Bonferroni over %d compared: %.0f%% for all together); "
                  "%d the change cannot reach: shown, never flagged",
                  perPassConfidence * 100.0, compared, familyConfidence * 100.0, notInfluenced);
    return buf;
}

ChangeVerdict judgeChange(const SeriesSamples& before, const SeriesSamples& after, const std::set<std::string>& influenced,
                          const std::vector<std::string>& order, double familyConfidence, int resamples) {
    std::vector<std::string> names;
    auto add = [&](const std::string& n) {
        if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
    };
    for (const auto& n : order)
        if (before.count(n) || after.count(n)) add(n);
    for (const auto& [n, v] : before) add(n);
    for (const auto& [n, v] : after) add(n);
    auto samples = [](const SeriesSamples& s, const std::string& n) {
        const auto it = s.find(n);
        return it == s.end() ? std::vector<double>{} : it->second;
    };
    ChangeVerdict v;
    v.familyConfidence = familyConfidence;
    for (const auto& n : names)
        if (seriesInfluenced(n, influenced) && !samples(before, n).empty() && !samples(after, n).empty()) ++v.compared;
    const double alpha = 1.0 - familyConfidence;
    v.perPassConfidence = 1.0 - alpha / std::max(v.compared, 1);
    for (const auto& n : names) {
        const std::vector<double> b = samples(before, n), a = samples(after, n);
        PassVerdict p;
        p.pass = n;
        p.influenced = seriesInfluenced(n, influenced);
        p.beforeFrames = static_cast<int>(b.size());
        p.afterFrames = static_cast<int>(a.size());
        if (!b.empty()) p.beforeMs = median(b);
        if (!a.empty()) p.afterMs = median(a);
        p.confidence = p.influenced ? v.perPassConfidence : familyConfidence;
        if (!a.empty() && !b.empty()) p.ratio = bootstrapRatioOfMedians(a, b, resamples, 12345, 1.0 - p.confidence);
        p.significant = p.influenced && p.ratio.valid() && (p.ratio.low > 1.0 || p.ratio.high < 1.0);
        v.notInfluenced += p.influenced ? 0 : 1;
        v.passes.push_back(std::move(p));
    }
    return v;
}

// ---- the measurement ----

std::vector<ChangeMeasurement::Slot> ChangeMeasurement::makeSchedule(const Settings& s) {
    std::vector<Slot> out;
    const int perTurn = std::max(s.perTurn, 1), settle = std::max(s.settle, 0);
    int counted[2] = {0, 0};
    // Before first, then after, turn by turn, until each side has its frames.
    for (bool after = false; counted[0] < s.framesPerSide || counted[1] < s.framesPerSide; after = !after) {
        int& c = counted[after ? 1 : 0];
        if (c >= s.framesPerSide) continue;
        for (int i = 0; i < settle; ++i) out.push_back({after, false});
        for (int i = 0; i < perTurn && c < s.framesPerSide; ++i, ++c) out.push_back({after, true});
    }
    return out;
}

void ChangeMeasurement::start(const KnobChange& change, const Settings& settings, std::set<std::string> influenced) {
    *this = ChangeMeasurement();
    change_ = change;
    settings_ = settings;
    settings_.framesPerSide = std::clamp(settings_.framesPerSide, 2, 150);
    influenced_ = std::move(influenced);
    schedule_ = makeSchedule(settings_);
    state_ = change_.empty() ? State::Idle : State::Rendering;
}

void ChangeMeasurement::setSide(KnobRegistry& knobs, bool after) {
    lastSet_.clear();
    for (size_t i = 0; i < change_.knobs.size(); ++i) {
        knobs.set(change_.knobs[i], after ? change_.after[i] : change_.before[i]);
        lastSet_.push_back(knobs.value(change_.knobs[i]));
    }
    generation_ = knobs.generation();
}

void ChangeMeasurement::restore(KnobRegistry& knobs) {
    for (size_t i = 0; i < change_.knobs.size(); ++i)
        if (i >= lastSet_.size() || knobs.value(change_.knobs[i]) == lastSet_[i]) knobs.set(change_.knobs[i], change_.after[i]);
    lastSet_.clear();
}

void ChangeMeasurement::cancel(KnobRegistry& knobs, const std::string& why) {
    if (!active()) return;
    restore(knobs);
    state_ = State::Cancelled;
    why_ = why;
}

bool ChangeMeasurement::prepareFrame(KnobRegistry& knobs) {
    if (state_ != State::Rendering) return false;
    if (!lastSet_.empty() && knobs.generation() != generation_) {
        cancel(knobs, "cancelled: a knob changed during the measurement");
        return false;
    }
    setSide(knobs, schedule_[next_].after);
    prepared_ = true;
    return true;
}

void ChangeMeasurement::frameRendered(std::uint64_t frameIndex) {
    if (state_ != State::Rendering || !prepared_) return;
    prepared_ = false;
    frames_[frameIndex] = schedule_[next_];
    lastFrame_ = frameIndex;
    if (++next_ >= schedule_.size()) state_ = State::Waiting;
}

bool ChangeMeasurement::collect(const PassTimer& timer, KnobRegistry& knobs, const std::vector<std::string>& order) {
    if (state_ != State::Waiting) return false;
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    const bool lastIn = total && !total->samples.empty() && total->samples.back().frame >= lastFrame_;
    if (!lastIn && timer.pendingFrames() > 0) return false;
    SeriesSamples before, after;
    for (const auto& s : timer.series())
        for (const auto& t : s.samples) {
            const auto it = frames_.find(t.frame);
            if (it == frames_.end() || !it->second.counted) continue;
            (it->second.after ? after : before)[s.name].push_back(t.gpuMs);
        }
    restore(knobs);
    verdict_ = judgeChange(before, after, influenced_, order);
    state_ = State::Done;
    return true;
}

float ChangeMeasurement::progress() const {
    if (schedule_.empty()) return 0.0f;
    if (state_ == State::Done) return 1.0f;
    return static_cast<float>(next_) / static_cast<float>(schedule_.size());
}

const char* ChangeMeasurement::stateName() const {
    switch (state_) {
        case State::Idle: return "idle";
        case State::Rendering: return "measuring";
        case State::Waiting: return "waiting";
        case State::Done: return "done";
        case State::Cancelled: return "cancelled";
    }
    return "";
}

std::string ChangeMeasurement::status() const {
    switch (state_) {
        case State::Idle: return "not measured";
        case State::Rendering:
            return "measuring: frame " + std::to_string(next_ + 1) + " of " + std::to_string(schedule_.size()) + " (" +
                   (schedule_[next_].after ? "after" : "before") + (schedule_[next_].counted ? "" : ", settling") + ")";
        case State::Waiting: return "waiting for the GPU times of the last frames";
        case State::Done: return "done";
        case State::Cancelled: return why_;
    }
    return "";
}

}  // namespace dw
