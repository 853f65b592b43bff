#include "renderer/bench/ConfigurationRunner.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>

#include "renderer/Error.h"
#include "renderer/gl/MemoryDomain.h"

namespace dw {

namespace {

using Clock = std::chrono::steady_clock;

std::string duration(double seconds) {
    const long s = std::lround(seconds);
    char text[32];
    std::snprintf(text, sizeof(text), "%ld:%02ld", s / 60, s % 60);
    return text;
}

// One counted frame, before its timings are harvested.
struct Counted {
    int config = 0;
    int sample = 0;
    long long seq = 0;
    std::size_t memPeak = 0;  // bytes (RunnerTimings::memoryPeak)
};

struct SessionFrames {
    std::map<std::uint64_t, Counted> counted;  // by frame index
    std::uint64_t harvestedUpTo = 0;            // frames up to here were handed out
    bool any = false;
};

// A configuration's series in pipeline order: each pass that ran, each of its
// spans after it, "frame" last; unknown series between the passes and "frame".
int rankOf(const std::map<std::string, int>& order, const std::string& series) {
    auto it = order.find(series);
    return it == order.end() ? 1 << 19 : it->second;
}

}  // namespace

std::string FrameWarnings::text(int countedFrames) const {
    std::string joined;
    for (const std::string& w : first) joined += (joined.empty() ? "" : "; ") + w;
    return joined + " (in " + std::to_string(frames) + " of " + std::to_string(countedFrames) +
           " counted frames; the first such frame's figures)";
}

ConfigurationRunner::ConfigurationRunner(RunnerPlan plan, Select select, Pose pose)
    : plan_(plan), select_(std::move(select)), pose_(std::move(pose)) {
    if (plan_.frames < 1) throw Error("at least one counted frame per configuration is needed");
    if (plan_.warmup < 0) throw Error("the warm-up frame count must not be negative");
    if (plan_.block < 1) throw Error("--block must be at least 1");
}

RenderSession& ConfigurationRunner::capture(int config, int sample, const FrameRequest& request) {
    RenderSession& session = select_(config);
    pose_(session, config, sample);
    session.render(request);
    return session;
}

double ConfigurationRunner::timeLeft(const std::vector<double>& roundSeconds, const std::vector<int>& roundsLeft) {
    double known = 0.0, sum = 0.0, unknownRounds = 0.0;
    int measured = 0;
    for (size_t c = 0; c < roundSeconds.size() && c < roundsLeft.size(); ++c) {
        if (roundSeconds[c] >= 0.0) {
            known += roundSeconds[c];
            ++measured;
            sum += roundSeconds[c] * roundsLeft[c];
        } else {
            unknownRounds += roundsLeft[c];
        }
    }
    return sum + (measured > 0 ? known / measured * unknownRounds : 0.0);
}

// What a measurement in progress holds between steps.
struct ConfigurationRunner::Measurement {
    std::string name;
    std::function<std::string(int)> describe;
    Progress progress;
    Stream stream;
    std::function<bool(int, int)> skip;
    Clock::time_point start = Clock::now();
    int roundCount = 0;
    // Every session once, to keep every counted frame's samples until the end.
    std::map<RenderSession*, SessionFrames> sessions;
    RunnerTimings out;
    std::map<int, std::map<std::string, int>> rank;  // config -> series -> pipeline order
    std::map<int, std::set<std::string>> seriesSeen;
    std::map<int, FrameReport> lastReport;
    // Wall seconds per round of each configuration (its warm-up and block), for the time left.
    std::vector<double> roundSeconds;
    std::vector<int> roundsLeft;
    long long total = 0, seq = 0;
    int previous = -1;
    double lastSaid = 0.0;
    int round = 0, config = 0;  // the next block to plan
    // The block being rendered, a frame a step: its configuration, round,
    // session, frames left (warm-up first: counted false) and start time.
    struct Frame {
        int sample = 0;
        bool counted = false;
    };
    std::deque<Frame> block;
    int blockConfig = -1, blockRound = 0;
    bool blockEndsRound = false;
    RenderSession* blockSession = nullptr;
    Clock::time_point blockStart;

    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
    bool skipped(int c, int k) const { return skip && skip(c, k); }
    void say(const std::string& line) const {
        if (progress) progress(line);
    }
    // The configuration's series ranked in the pipeline order of its last frame.
    void updateRank(int c, const FrameReport& report) {
        std::map<std::string, int>& order = rank[c];
        order.clear();
        for (const PassRecord& rec : report.passes) {
            if (!rec.ran) continue;
            order.emplace(rec.name, static_cast<int>(order.size()));
            for (const auto& series : seriesSeen[c])
                if (series.rfind(rec.name + "/", 0) == 0) order.emplace(series, static_cast<int>(order.size()));
        }
        order.emplace(PassTimer::kFrameSeries, 1 << 20);
    }
    bool before(const BenchSample& a, const BenchSample& b) {
        if (a.config != b.config) return a.config < b.config;
        if (a.sample != b.sample) return a.sample < b.sample;
        const int ia = rankOf(rank[a.config], a.series), ib = rankOf(rank[b.config], b.series);
        return ia != ib ? ia < ib : a.series < b.series;
    }
    void sortSamples(std::vector<BenchSample>& samples) {
        std::sort(samples.begin(), samples.end(), [this](const BenchSample& a, const BenchSample& b) { return before(a, b); });
    }
    void harvest(bool wait);
    void harvestSession(RenderSession& session, SessionFrames& frames, bool wait, std::vector<BenchSample>& fresh);
};

// One session's finished counted frames, moved out of its timer into `fresh`.
void ConfigurationRunner::Measurement::harvestSession(RenderSession& session, SessionFrames& frames, bool wait,
                                                      std::vector<BenchSample>& fresh) {
    PassTimer& timer = session.pipeline().timer();
    timer.collect(wait);
    std::uint64_t newest = frames.harvestedUpTo;
    bool any = false;
    for (const auto& series : timer.series()) {
        for (auto it = series.samples.rbegin(); it != series.samples.rend(); ++it) {
            const TimingSample& t = *it;
            if (frames.any && t.frame <= frames.harvestedUpTo) break;
            newest = any ? std::max(newest, t.frame) : t.frame;
            any = true;
            auto c = frames.counted.find(t.frame);
            if (c == frames.counted.end()) continue;
            BenchSample b;
            b.config = c->second.config;
            b.sample = c->second.sample;
            b.seq = c->second.seq;
            b.frame = t.frame;
            b.series = series.name;
            // To the CSV's 0.1 µs, so that the tables of this run and of
            // `bench merge` over its CSV are made from the same numbers.
            b.gpuMs = std::round(double{t.gpuMs} * 1e4) / 1e4;
            b.cpuMs = std::round(double{t.cpuMs} * 1e4) / 1e4;
            b.counts = t.counts;
            b.gpuMemPeakMib = static_cast<double>(c->second.memPeak) / (1024.0 * 1024.0);
            seriesSeen[b.config].insert(b.series);
            fresh.push_back(std::move(b));
        }
    }
    if (any) {
        frames.harvestedUpTo = std::max(frames.harvestedUpTo, newest);
        frames.any = true;
    }
}

// Moves the finished counted frames' samples out of the timers (and to the stream).
void ConfigurationRunner::Measurement::harvest(bool wait) {
    std::vector<BenchSample> fresh;
    for (auto& [session, frames] : sessions) harvestSession(*session, frames, wait, fresh);
    for (auto& [c, report] : lastReport) updateRank(c, report);
    sortSamples(fresh);
    if (stream && !fresh.empty()) stream(fresh);
    for (auto& sample : fresh) out.samples.push_back(std::move(sample));
}

ConfigurationRunner::~ConfigurationRunner() = default;
ConfigurationRunner::ConfigurationRunner(ConfigurationRunner&&) noexcept = default;
ConfigurationRunner& ConfigurationRunner::operator=(ConfigurationRunner&&) noexcept = default;

void ConfigurationRunner::begin(const std::string& name, const std::function<std::string(int)>& describe,
                                const Progress& progress, const Stream& stream,
                                const std::function<bool(int, int)>& skip) {
    m_ = std::make_unique<Measurement>();
    Measurement& m = *m_;
    m.name = name;
    m.describe = describe;
    m.progress = progress;
    m.stream = stream;
    m.skip = skip;
    m.roundCount = rounds();
    const int configs = plan_.configurations;
    std::vector<RenderSession*> sessionOf(static_cast<size_t>(configs), nullptr);
    for (int c = 0; c < configs; ++c) sessionOf[static_cast<size_t>(c)] = &select_(c);
    const size_t perSession = static_cast<size_t>(configs) * static_cast<size_t>(m.roundCount * plan_.warmup + plan_.frames);
    for (RenderSession* s : sessionOf) {
        m.sessions[s];
        if (plan_.counters) s->pipeline().timer().setCounting(true);
        s->pipeline().timer().setHistoryLength(std::max({PassTimer::kHistory, perSession + 64, s->pipeline().timer().historyLength()}));
    }
    m.roundSeconds.assign(static_cast<size_t>(configs), -1.0);
    m.roundsLeft.assign(static_cast<size_t>(configs), 0);
    for (int c = 0; c < configs; ++c)
        for (int r = 0; r < m.roundCount; ++r) {
            bool any = false;
            for (int k = r * plan_.block; k < std::min(plan_.frames, (r + 1) * plan_.block); ++k)
                if (!m.skipped(c, k)) {
                    any = true;
                    ++m.total;
                }
            m.roundsLeft[static_cast<size_t>(c)] += any ? 1 : 0;
        }
}

bool ConfigurationRunner::step() {
    if (!m_) throw Error("ConfigurationRunner::step before begin");
    Measurement& m = *m_;
    if (plan_.configurations < 1) return false;
    while (m.block.empty()) {
        if (m.round >= m.roundCount) return false;
        planBlock();
    }
    renderFrame();
    if (m.block.empty()) endBlock();
    return !m.block.empty() || m.round < m.roundCount;
}

double ConfigurationRunner::fractionDone() const {
    return m_ && m_->total > 0 ? static_cast<double>(m_->seq) / static_cast<double>(m_->total) : 0.0;
}

// The next configuration's block of the round: its warm-up after a switch
// (every block when there is more than one configuration), then its counted
// frames not skipped. A block whose counted frames are all skipped is empty
// (nothing rendered, not even its warm-up); the round ends after its last
// configuration's block either way.
void ConfigurationRunner::planBlock() {
    Measurement& m = *m_;
    const int c = m.config;
    if (++m.config == plan_.configurations) m.config = 0;
    m.blockConfig = c;
    m.blockRound = m.round;
    m.blockEndsRound = m.config == 0;
    const int first = m.round * plan_.block, count = std::min(plan_.block, plan_.frames - first);
    std::vector<int> pending;
    for (int j = 0; j < count; ++j)
        if (!m.skipped(c, first + j)) pending.push_back(first + j);
    if (!pending.empty()) {
        if (c != m.previous)
            for (int w = 0; w < plan_.warmup; ++w) m.block.push_back({pending.front(), false});
        for (int k : pending) m.block.push_back({k, true});
        m.blockStart = Clock::now();
        m.blockSession = &select_(c);
        m.previous = c;
    } else {
        endRound();
    }
}

// The block's next frame: posed, rendered with the plan's request; a counted
// one noted for the harvest (and its warnings kept).
void ConfigurationRunner::renderFrame() {
    Measurement& m = *m_;
    const Measurement::Frame f = m.block.front();
    m.block.pop_front();
    const int c = m.blockConfig;
    // Selected again before every frame when the caller's own loop changes
    // the session between steps (the window); else once a block.
    RenderSession& session = plan_.selectEveryFrame ? select_(c) : *m.blockSession;
    pose_(session, c, f.sample);
    const void* domain = &session.pipeline();
    if (f.counted) gl::resetDomainPeak(domain);
    FrameReport report = session.render(plan_.request);
    if (!f.counted) return;
    std::size_t& peak = m.out.memoryPeak[c];
    peak = std::max(peak, gl::domainPeakBytes(domain));
    m.sessions.at(&session).counted[report.frameIndex] = {c, f.sample, m.seq++, gl::domainPeakBytes(domain)};
    if (std::vector<std::string> said = report.warnings(); !said.empty()) {
        FrameWarnings& w = m.out.warnings[c];
        if (w.frames++ == 0) w.first = std::move(said);
    }
    m.lastReport[c] = std::move(report);
}

// After a block's last frame: its wall time for the time left, a progress
// line every 2 s, and the end of the round after its last configuration.
void ConfigurationRunner::endBlock() {
    Measurement& m = *m_;
    const int c = m.blockConfig;
    m.roundSeconds[static_cast<size_t>(c)] = std::chrono::duration<double>(Clock::now() - m.blockStart).count();
    --m.roundsLeft[static_cast<size_t>(c)];
    if (m.elapsed() - m.lastSaid > 2.0) sayProgress(m.blockRound, c);
    if (m.blockEndsRound) endRound();
}

// A round ends: its samples streamed (when a caller takes them as they come).
void ConfigurationRunner::endRound() {
    Measurement& m = *m_;
    if (!m.blockEndsRound) return;
    if (m.stream) m.harvest(false);
    ++m.round;
}

void ConfigurationRunner::sayProgress(int round, int c) {
    Measurement& m = *m_;
    const int configs = plan_.configurations;
    m.lastSaid = m.elapsed();
    // Configurations not timed yet count at the mean of those timed: say how many, since
    // a slow one among them (fullscreen at 10 000 lights) makes the estimate low.
    int untimed = 0;
    for (int k = 0; k < configs; ++k)
        untimed += m.roundSeconds[static_cast<size_t>(k)] < 0.0 && m.roundsLeft[static_cast<size_t>(k)] > 0;
    m.say(m.name + ": frame " + std::to_string(m.seq) + "/" + std::to_string(m.total) + " (round " +
          std::to_string(round + 1) + "/" + std::to_string(m.roundCount) + "), " + duration(m.lastSaid) +
          " elapsed, about " + duration(timeLeft(m.roundSeconds, m.roundsLeft)) + " left" +
          (untimed > 0 ? " (" + std::to_string(untimed) + " of " + std::to_string(configs) +
                             " configurations not timed yet)"
                       : std::string()) +
          "; now " + (m.describe ? m.describe(c) : std::to_string(c)));
}

RunnerTimings ConfigurationRunner::finish() {
    if (!m_) throw Error("ConfigurationRunner::finish before begin");
    Measurement& m = *m_;
    m.harvest(true);
    // Every frame's series in its configuration's final pipeline order.
    for (auto& [config, report] : m.lastReport) m.updateRank(config, report);
    m.sortSamples(m.out.samples);
    for (auto& [config, report] : m.lastReport)
        for (const PassRecord& rec : report.passes)
            if (rec.ran && !rec.stats.empty()) m.out.stats[config][rec.name] = rec.stats;
    m.out.seconds = m.elapsed();
    RunnerTimings out = std::move(m.out);
    m_.reset();
    return out;
}

RunnerTimings ConfigurationRunner::measure(const std::string& name, const std::function<std::string(int)>& describe,
                                           const Progress& progress, const Stream& stream,
                                           const std::function<bool(int, int)>& skip) {
    begin(name, describe, progress, stream, skip);
    while (step()) {
    }
    return finish();
}

}  // namespace dw
