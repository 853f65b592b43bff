#include "renderer/bench/ConfigurationRunner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>

#include "renderer/Error.h"

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

RunnerTimings ConfigurationRunner::measure(const std::string& name, const std::function<std::string(int)>& describe,
                                           const Progress& progress, const Stream& stream,
                                           const std::function<bool(int, int)>& skip) {
    auto say = [&](const std::string& line) {
        if (progress) progress(line);
    };
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    const int configs = plan_.configurations;
    const int roundCount = rounds();
    auto skipped = [&](int c, int k) { return skip && skip(c, k); };

    // Every session once, to keep every counted frame's samples until the end.
    std::map<RenderSession*, SessionFrames> sessions;
    std::vector<RenderSession*> sessionOf(static_cast<size_t>(configs), nullptr);
    for (int c = 0; c < configs; ++c) sessionOf[static_cast<size_t>(c)] = &select_(c);
    const size_t perSession = static_cast<size_t>(configs) * static_cast<size_t>(roundCount * plan_.warmup + plan_.frames);
    for (RenderSession* s : sessionOf) {
        sessions[s];
        s->pipeline().timer().setHistoryLength(std::max({PassTimer::kHistory, perSession + 64, s->pipeline().timer().historyLength()}));
    }

    RunnerTimings out;
    std::map<int, std::map<std::string, int>> rank;  // config -> series -> pipeline order
    std::map<int, std::set<std::string>> seriesSeen;
    auto updateRank = [&](int config, const FrameReport& report) {
        std::map<std::string, int>& order = rank[config];
        order.clear();
        for (const PassRecord& rec : report.passes) {
            if (!rec.ran) continue;
            order.emplace(rec.name, static_cast<int>(order.size()));
            for (const auto& s : seriesSeen[config])
                if (s.rfind(rec.name + "/", 0) == 0) order.emplace(s, static_cast<int>(order.size()));
        }
        order.emplace(PassTimer::kFrameSeries, 1 << 20);
    };
    std::map<int, FrameReport> lastReport;
    auto before = [&](const BenchSample& a, const BenchSample& b) {
        if (a.config != b.config) return a.config < b.config;
        if (a.sample != b.sample) return a.sample < b.sample;
        const int ia = rankOf(rank[a.config], a.series), ib = rankOf(rank[b.config], b.series);
        return ia != ib ? ia < ib : a.series < b.series;
    };
    // Moves the finished counted frames' samples out of the timers.
    auto harvest = [&](bool wait) {
        std::vector<BenchSample> fresh;
        for (auto& [session, frames] : sessions) {
            PassTimer& timer = session->pipeline().timer();
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
                    seriesSeen[b.config].insert(b.series);
                    fresh.push_back(std::move(b));
                }
            }
            if (any) {
                frames.harvestedUpTo = std::max(frames.harvestedUpTo, newest);
                frames.any = true;
            }
        }
        for (auto& [config, report] : lastReport) updateRank(config, report);
        std::sort(fresh.begin(), fresh.end(), before);
        if (stream && !fresh.empty()) stream(fresh);
        for (auto& s : fresh) out.samples.push_back(std::move(s));
    };

    // Wall seconds per round of each configuration (its warm-up and block), for the time left.
    std::vector<double> roundSeconds(static_cast<size_t>(configs), -1.0);
    std::vector<int> roundsLeft(static_cast<size_t>(configs), 0);
    long long total = 0;
    for (int c = 0; c < configs; ++c)
        for (int r = 0; r < roundCount; ++r) {
            bool any = false;
            for (int k = r * plan_.block; k < std::min(plan_.frames, (r + 1) * plan_.block); ++k)
                if (!skipped(c, k)) {
                    any = true;
                    ++total;
                }
            roundsLeft[static_cast<size_t>(c)] += any ? 1 : 0;
        }

    long long seq = 0;
    int previous = -1;
    double lastSaid = 0.0;
    const FrameRequest request;  // the final image, as a user would see it
    for (int round = 0; round < roundCount; ++round) {
        for (int c = 0; c < configs; ++c) {
            const int first = round * plan_.block, count = std::min(plan_.block, plan_.frames - first);
            std::vector<int> pending;
            for (int j = 0; j < count; ++j)
                if (!skipped(c, first + j)) pending.push_back(first + j);
            if (pending.empty()) continue;
            const auto roundStart = Clock::now();
            RenderSession& session = select_(c);
            SessionFrames& frames = sessions.at(&session);
            // Warm-up after a switch (every block when there is more than one configuration).
            if (c != previous)
                for (int w = 0; w < plan_.warmup; ++w) {
                    pose_(session, c, pending.front());
                    session.render(request);
                }
            previous = c;
            for (int k : pending) {
                pose_(session, c, k);
                FrameReport report = session.render(request);
                frames.counted[report.frameIndex] = {c, k, seq++};
                lastReport[c] = std::move(report);
            }
            roundSeconds[static_cast<size_t>(c)] = std::chrono::duration<double>(Clock::now() - roundStart).count();
            --roundsLeft[static_cast<size_t>(c)];
            if (elapsed() - lastSaid > 2.0) {
                lastSaid = elapsed();
                // Configurations not timed yet count at the mean of those timed: say how many, since
                // a slow one among them (fullscreen at 10 000 lights) makes the estimate low.
                int untimed = 0;
                for (int k = 0; k < configs; ++k)
                    untimed += roundSeconds[static_cast<size_t>(k)] < 0.0 && roundsLeft[static_cast<size_t>(k)] > 0;
                say(name + ": frame " + std::to_string(seq) + "/" + std::to_string(total) + " (round " +
                    std::to_string(round + 1) + "/" + std::to_string(roundCount) + "), " + duration(lastSaid) +
                    " elapsed, about " + duration(timeLeft(roundSeconds, roundsLeft)) + " left" +
                    (untimed > 0 ? " (" + std::to_string(untimed) + " of " + std::to_string(configs) +
                                       " configurations not timed yet)"
                                 : std::string()) +
                    "; now " + (describe ? describe(c) : std::to_string(c)));
            }
        }
        if (stream) harvest(false);
    }
    harvest(true);
    // Every frame's series in its configuration's final pipeline order.
    for (auto& [config, report] : lastReport) updateRank(config, report);
    std::sort(out.samples.begin(), out.samples.end(), before);
    for (auto& [config, report] : lastReport)
        for (const PassRecord& rec : report.passes)
            if (rec.ran && !rec.stats.empty()) out.stats[config][rec.name] = rec.stats;
    out.seconds = elapsed();
    return out;
}

}  // namespace dw
