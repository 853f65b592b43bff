#include "renderer/graph/PassTimer.h"

#include <algorithm>
#include <fstream>
#include <numeric>
#include <sstream>

#include "renderer/Error.h"
#include "renderer/gl/Fence.h"

namespace dw {

TimingStats computeStats(std::vector<float> v) {
    TimingStats s;
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    s.count = static_cast<int>(v.size());
    s.min = v.front();
    s.max = v.back();
    const size_t n = v.size();
    s.median = n % 2 ? v[n / 2] : 0.5f * (v[n / 2 - 1] + v[n / 2]);
    s.mean = static_cast<float>(std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(n));
    return s;
}

gl::TimestampQuery PassTimer::acquire() {
    if (pool_.empty()) return gl::TimestampQuery::create();
    gl::TimestampQuery q = std::move(pool_.back());
    pool_.pop_back();
    return q;
}

gl::CounterQueries PassTimer::acquireCounters() {
    if (counterPool_.empty()) return gl::CounterQueries::create(statistics_);
    gl::CounterQueries q = std::move(counterPool_.back());
    counterPool_.pop_back();
    return q;
}

void PassTimer::release(Span& s) {
    if (s.begin) pool_.push_back(std::move(s.begin));
    if (s.end) pool_.push_back(std::move(s.end));
    if (s.counters && s.counters.statistics() == statistics_) counterPool_.push_back(std::move(s.counters));
    s.counters = {};
}

void PassTimer::setCounting(bool on) {
    if (on && !counting_) statistics_ = gl::hasPipelineStatistics();
    counting_ = on;
}

void PassTimer::setPassBytes(std::int64_t bytes) {
    if (inPass_) current_.spans[passIndex_].bytes = bytes;
}

void PassTimer::beginFrame(std::uint64_t frame) {
    if (inFrame_) throw Error("PassTimer::beginFrame called twice");
    collect(false);
    current_ = PendingFrame{};
    current_.frame = frame;
    inFrame_ = true;
    frameStart_ = std::chrono::steady_clock::now();
    Span whole;
    whole.name = kFrameSeries;
    whole.begin = acquire();
    whole.begin.record();
    current_.spans.push_back(std::move(whole));
}

void PassTimer::beginPass(const std::string& name) {
    if (!inFrame_ || inPass_) throw Error("PassTimer::beginPass outside a frame or inside a pass");
    if (isolateCpu_) gl::waitForGpu();
    Span s;
    s.name = name;
    s.begin = acquire();
    s.begin.record();
    if (counting_) {
        s.counters = acquireCounters();
        s.counters.begin();
    }
    current_.spans.push_back(std::move(s));
    inPass_ = true;
    passName_ = name;
    passIndex_ = current_.spans.size() - 1;
    passStart_ = std::chrono::steady_clock::now();
}

void PassTimer::beginSubSpan(const std::string& name) {
    if (!inPass_ || inSubSpan_) throw Error("PassTimer::beginSubSpan outside a pass or inside a sub-span");
    Span s;
    s.name = passName_ + "/" + name;
    s.begin = acquire();
    s.begin.record();
    current_.spans.push_back(std::move(s));
    inSubSpan_ = true;
    subStart_ = std::chrono::steady_clock::now();
}

void PassTimer::endSubSpan() {
    if (!inSubSpan_) throw Error("PassTimer::endSubSpan without beginSubSpan");
    Span& s = current_.spans.back();
    s.end = acquire();
    s.end.record();
    s.cpuMs = std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - subStart_).count();
    inSubSpan_ = false;
}

void PassTimer::endPass() {
    if (!inPass_ || inSubSpan_) throw Error("PassTimer::endPass without beginPass, or inside a sub-span");
    Span& s = current_.spans[passIndex_];
    if (s.counters) s.counters.end();
    s.end = acquire();
    s.end.record();
    s.cpuMs = std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - passStart_).count();
    inPass_ = false;
}

void PassTimer::endFrame() {
    if (!inFrame_) throw Error("PassTimer::endFrame without beginFrame");
    Span& whole = current_.spans.front();
    whole.end = acquire();
    whole.end.record();
    whole.cpuMs = std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - frameStart_).count();
    pending_.push_back(std::move(current_));
    inFrame_ = false;
}

void PassTimer::abortFrame() {
    if (inPass_ && current_.spans[passIndex_].counters) current_.spans[passIndex_].counters.end();
    for (auto& s : current_.spans) release(s);
    current_ = PendingFrame{};
    inFrame_ = inPass_ = inSubSpan_ = false;
}

PassTimer::Series& PassTimer::seriesFor(const std::string& name) {
    for (auto& s : series_)
        if (s.name == name) return s;
    series_.push_back(Series{name, {}});
    return series_.back();
}

namespace {
// A pass's counters in PassCounts order, from the queries' (CounterQueries::targets) order.
PassCounts countsOf(const gl::CounterQueries& q, std::int64_t bytes) {
    const auto r = q.results();
    PassCounts c;
    c.v = {r[0], r[4], r[1], r[2], r[3], bytes};
    return c;
}
}  // namespace

void PassTimer::harvest(PendingFrame& f) {
    // Spans with the same name in one frame (sub-spans) are added up; the
    // frame's counters are the sum of its passes'.
    std::vector<std::pair<std::string, TimingSample>> sums;
    PassCounts frameCounts;
    for (auto& span : f.spans) {
        const std::uint64_t t0 = span.begin.result(), t1 = span.end.result();
        const float gpu = t1 > t0 ? static_cast<float>(static_cast<double>(t1 - t0) * 1e-6) : 0.0f;
        TimingSample sample{f.frame, gpu, span.cpuMs, {}};
        if (span.counters) {
            sample.counts = countsOf(span.counters, span.bytes);
            frameCounts.add(sample.counts);
        }
        auto it = std::find_if(sums.begin(), sums.end(), [&](const auto& p) { return p.first == span.name; });
        if (it == sums.end()) {
            sums.push_back({span.name, sample});
        } else {
            it->second.gpuMs += gpu;
            it->second.cpuMs += span.cpuMs;
            it->second.counts.add(sample.counts);
        }
        release(span);
    }
    for (auto& [name, sample] : sums) {
        if (name == kFrameSeries) sample.counts = frameCounts;
        addSample(name, sample);
    }
}

void PassTimer::addSample(const std::string& series, const TimingSample& sample) {
    if (paused_ || sample.frame < floor_) return;
    Series& s = seriesFor(series);
    s.samples.push_back(sample);
    while (s.samples.size() > historyLength_) s.samples.pop_front();
}

void PassTimer::setHistoryLength(size_t samples) {
    historyLength_ = std::max<size_t>(samples, 1);
    for (auto& s : series_)
        while (s.samples.size() > historyLength_) s.samples.pop_front();
}

void PassTimer::collect(bool wait) {
    while (!pending_.empty()) {
        PendingFrame& f = pending_.front();
        if (!wait) {
            bool ready = true;
            for (const auto& s : f.spans)
                ready = ready && s.begin.available() && s.end.available() && (!s.counters || s.counters.available());
            if (!ready) break;
        }
        harvest(f);
        pending_.pop_front();
    }
}

const PassTimer::Series* PassTimer::find(const std::string& name) const {
    for (const auto& s : series_)
        if (s.name == name) return &s;
    return nullptr;
}

namespace {
template <typename F>
TimingStats statsOf(const PassTimer::Series* s, size_t window, F field) {
    if (!s) return {};
    std::vector<float> v;
    const size_t n = s->samples.size();
    const size_t start = window == 0 || window >= n ? 0 : n - window;
    for (size_t i = start; i < n; ++i) v.push_back(field(s->samples[i]));
    return computeStats(std::move(v));
}
}  // namespace

TimingStats PassTimer::gpuStats(const std::string& name, size_t window) const {
    return statsOf(find(name), window, [](const TimingSample& t) { return t.gpuMs; });
}

TimingStats PassTimer::cpuStats(const std::string& name, size_t window) const {
    return statsOf(find(name), window, [](const TimingSample& t) { return t.cpuMs; });
}

void PassTimer::clearHistory() { series_.clear(); }

void PassTimer::clearHistoryBefore(std::uint64_t frame) {
    floor_ = std::max(floor_, frame);
    for (auto& s : series_)
        while (!s.samples.empty() && s.samples.front().frame < frame) s.samples.pop_front();
    series_.erase(std::remove_if(series_.begin(), series_.end(), [](const Series& s) { return s.samples.empty(); }),
                  series_.end());
}

std::string PassTimer::csv() const {
    std::ostringstream out;
    out << "frame,series,gpu_ms,cpu_ms\n";
    out.setf(std::ios::fixed);
    out.precision(4);
    for (const auto& s : series_)
        for (const auto& t : s.samples) out << t.frame << "," << s.name << "," << t.gpuMs << "," << t.cpuMs << "\n";
    return out.str();
}

void PassTimer::writeCsv(const std::string& path) const {
    std::ofstream f(path, std::ios::trunc);
    if (!f) throw FileError(path, "cannot write the timing CSV");
    f << csv();
    if (!f) throw FileError(path, "writing the timing CSV failed");
}

}  // namespace dw
