#include "renderer/bench/TradeoffEvidence.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "renderer/graph/PassTimer.h"
#include "renderer/metrics/Bootstrap.h"

namespace dw {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// round -> the row's frame times in that round (every configuration of the row).
std::map<int, std::vector<double>> byRound(const RowData& row, int block) {
    std::map<int, std::vector<double>> rounds;
    for (const auto* frames : row.frames)
        if (frames)
            for (const auto& [sample, ms] : *frames) rounds[sample / std::max(1, block)].push_back(ms);
    return rounds;
}

std::vector<double> timeDraws(const RowData& row, const EvidenceDraws& how) {
    const std::map<int, std::vector<double>> rounds = byRound(row, how.block);
    std::vector<double> draws;
    // Fewer rounds than an interval of a median needs (Bootstrap.h: 6): a
    // bootstrap over so few only repeats them (3 rounds in one order would
    // "differ" at p = 0.001), so time is not told apart.
    if (!enoughForInterval(rounds.size())) return draws;
    // Every row resamples rounds 0 .. R-1 by the same generator: a round the
    // row lacks (none of its frames in it) is skipped, the others paired.
    const int roundCount = rounds.rbegin()->first + 1;
    std::mt19937_64 rng(how.seed);
    std::vector<double> v;
    draws.reserve(static_cast<size_t>(how.resamples));
    for (int b = 0; b < how.resamples; ++b) {
        v.clear();
        for (int k = 0; k < roundCount; ++k) {
            const auto it = rounds.find(static_cast<int>(bootstrapIndex(rng, static_cast<size_t>(roundCount))));
            if (it != rounds.end()) v.insert(v.end(), it->second.begin(), it->second.end());
        }
        draws.push_back(v.empty() ? kNaN : median(v));
    }
    if (std::any_of(draws.begin(), draws.end(), [](double d) { return std::isnan(d); })) draws.clear();
    return draws;
}

std::vector<double> errorDraws(const RowData& row, const EvidenceDraws& how) {
    std::vector<double> sum(static_cast<size_t>(how.resamples), 0.0), count(sum.size(), 0.0);
    for (size_t c = 0; c < row.tiles.size(); ++c) {
        const ErrorTiles* t = row.tiles[c];
        if (!t || t->sums.empty()) continue;
        std::mt19937_64 rng(how.seed + 1 + c);  // camera c's tiles: the same draws in every row
        for (int b = 0; b < how.resamples; ++b) {
            double s = 0.0, n = 0.0;
            for (size_t k = 0; k < t->sums.size(); ++k) {
                const size_t j = bootstrapIndex(rng, t->sums.size());
                s += t->sums[j];
                n += t->counts[j];
            }
            const double v = t->valueOf(s, n);
            if (std::isnan(v)) return {};
            sum[static_cast<size_t>(b)] += v;
            count[static_cast<size_t>(b)] += 1.0;
        }
    }
    std::vector<double> draws;
    if (count.empty() || count.front() == 0.0) return draws;
    for (size_t b = 0; b < sum.size(); ++b) {
        const double mean = sum[b] / count[b];  // over the cameras (one for a camera's row)
        draws.push_back(row.lowerIsBetter ? mean : -mean);
    }
    return draws;
}

}  // namespace

FrameTimes frameTimes(const std::vector<BenchSample>& samples, const std::vector<std::string>& terms) {
    const bool frame = terms.size() == 1 && terms.front() == PassTimer::kFrameSeries;
    FrameTimes out;
    for (const auto& s : samples) {
        const bool counted = frame ? s.series == PassTimer::kFrameSeries
                                   : std::find(terms.begin(), terms.end(), s.series) != terms.end();
        if (counted) out[s.config][s.sample] += s.gpuMs;  // the terms of one frame, summed
    }
    return out;
}

FrontEvidence rowEvidence(const RowData& row, const EvidenceDraws& how) {
    FrontEvidence e;
    e.cost.value = row.time;
    e.cost.lo = e.cost.hi = kNaN;
    e.cost.draws = timeDraws(row, how);
    e.error.value = row.lowerIsBetter ? row.error : -row.error;
    e.error.lo = e.error.hi = kNaN;
    e.error.draws = errorDraws(row, how);
    return e;
}

}  // namespace dw
