#include "renderer/graph/ChangeCost.h"

#include <cmath>
#include <cstdio>

namespace dw {

std::string PassChangeCost::describe() const {
    char buf[160];
    if (beforeFrames == 0 && afterFrames > 0) {
        std::snprintf(buf, sizeof(buf), "new: %.3f ms", afterMs);
        return buf;
    }
    if (afterFrames == 0) return "no frames since";
    if (!ratio.valid()) return "no data";
    const double diff = afterMs - beforeMs;
    std::snprintf(buf, sizeof(buf), "%+.*f ms (%+.0f%%, 95%% CI %+.0f%% to %+.0f%%)", std::fabs(diff) < 1.0 ? 3 : 1, diff,
                  (ratio.ratio - 1.0) * 100.0, (ratio.low - 1.0) * 100.0, (ratio.high - 1.0) * 100.0);
    return buf;
}

void ChangeCost::mark(const PassTimer& timer, std::uint64_t lastFrameBefore, std::string what, size_t window,
                      std::uint64_t settle, std::uint64_t firstFrame) {
    active_ = true;
    what_ = std::move(what);
    window_ = window;
    firstAfter_ = lastFrameBefore + 1 + settle;
    before_.clear();
    for (const auto& s : timer.series()) {
        std::vector<double> v;
        for (auto it = s.samples.rbegin(); it != s.samples.rend() && v.size() < window; ++it)
            if (it->frame <= lastFrameBefore && it->frame >= firstFrame) v.push_back(it->gpuMs);
        if (!v.empty()) before_.emplace_back(s.name, std::move(v));
    }
}

std::vector<PassChangeCost> ChangeCost::costs(const PassTimer& timer) const {
    std::vector<PassChangeCost> out;
    if (!active_) return out;
    for (const auto& [name, before] : before_) {
        PassChangeCost c;
        c.pass = name;
        c.beforeFrames = static_cast<int>(before.size());
        c.beforeMs = median(before);
        std::vector<double> after;
        if (const PassTimer::Series* s = timer.find(name))
            for (const auto& t : s->samples)
                if (t.frame >= firstAfter_ && after.size() < window_) after.push_back(t.gpuMs);
        c.afterFrames = static_cast<int>(after.size());
        if (!after.empty()) {
            c.afterMs = median(after);
            c.ratio = bootstrapRatioOfMedians(after, before, 1000);
        }
        out.push_back(std::move(c));
    }
    // Passes that run only since the change (a pass switched on).
    for (const auto& s : timer.series()) {
        bool known = false;
        for (const auto& b : before_) known = known || b.first == s.name;
        if (known) continue;
        std::vector<double> after;
        for (const auto& t : s.samples)
            if (t.frame >= firstAfter_ && after.size() < window_) after.push_back(t.gpuMs);
        if (after.empty()) continue;
        PassChangeCost c;
        c.pass = s.name;
        c.afterFrames = static_cast<int>(after.size());
        c.afterMs = median(after);
        out.push_back(std::move(c));
    }
    return out;
}

int ChangeCost::afterFrames(const PassTimer& timer) const {
    const PassTimer::Series* s = timer.find(PassTimer::kFrameSeries);
    if (!active_ || !s) return 0;
    int n = 0;
    for (const auto& t : s->samples)
        if (t.frame >= firstAfter_) ++n;
    return n;
}

}  // namespace dw
