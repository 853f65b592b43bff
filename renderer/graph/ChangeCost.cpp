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

}  // namespace dw
