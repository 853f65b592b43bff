#include "renderer/bench/DifferenceInterval.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "renderer/bench/Bootstrap.h"

namespace dw {

namespace {

// In [0, n), the same on every platform (rejection sampling, unbiased).
size_t draw(std::mt19937_64& rng, size_t n) {
    const std::uint64_t limit = std::mt19937_64::max() - std::mt19937_64::max() % n;
    std::uint64_t x;
    do x = rng();
    while (x >= limit);
    return static_cast<size_t>(x % n);
}

double percentile(const std::vector<double>& sorted, double p) {
    const double pos = p * static_cast<double>(sorted.size() - 1);
    const size_t i = static_cast<size_t>(std::floor(pos));
    const size_t j = std::min(i + 1, sorted.size() - 1);
    return sorted[i] + (sorted[j] - sorted[i]) * (pos - static_cast<double>(i));
}

}  // namespace

DifferenceInterval bootstrapDifferenceOfMedians(const std::vector<double>& a, const std::vector<double>& b,
                                                int resamples, std::uint64_t seed, double alpha) {
    DifferenceInterval r;
    if (a.empty() || b.empty() || resamples <= 0) return r;
    r.difference = median(a) - median(b);
    std::mt19937_64 rng(seed);
    std::vector<double> ra(a.size()), rb(b.size()), differences;
    differences.reserve(static_cast<size_t>(resamples));
    for (int i = 0; i < resamples; ++i) {
        for (auto& v : ra) v = a[draw(rng, a.size())];
        for (auto& v : rb) v = b[draw(rng, b.size())];
        differences.push_back(median(ra) - median(rb));
    }
    std::sort(differences.begin(), differences.end());
    r.low = percentile(differences, alpha / 2.0);
    r.high = percentile(differences, 1.0 - alpha / 2.0);
    r.resamples = resamples;
    return r;
}

}  // namespace dw
