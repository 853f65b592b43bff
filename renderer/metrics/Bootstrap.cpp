#include "renderer/metrics/Bootstrap.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace dw {

namespace {

// In [0, n): the same on every platform (std::uniform_int_distribution is not).
size_t draw(std::mt19937_64& rng, size_t n) {
    // Rejection keeps it unbiased; n is tiny next to 2^64, so it almost never loops.
    const std::uint64_t limit = std::mt19937_64::max() - std::mt19937_64::max() % n;
    std::uint64_t x;
    do x = rng();
    while (x >= limit);
    return static_cast<size_t>(x % n);
}

double medianInPlace(std::vector<double>& v) {
    const size_t n = v.size();
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(n / 2);
    std::nth_element(v.begin(), mid, v.end());
    if (n % 2) return *mid;
    return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

// Linear interpolation between closest ranks of a sorted vector.
double percentile(const std::vector<double>& sorted, double p) {
    const double pos = p * static_cast<double>(sorted.size() - 1);
    const size_t i = static_cast<size_t>(std::floor(pos));
    const size_t j = std::min(i + 1, sorted.size() - 1);
    return sorted[i] + (sorted[j] - sorted[i]) * (pos - static_cast<double>(i));
}

}  // namespace

std::size_t bootstrapIndex(std::mt19937_64& rng, std::size_t n) { return draw(rng, n); }

double median(std::vector<double> values) { return values.empty() ? 0.0 : medianInPlace(values); }

MedianInterval bootstrapMedian(const std::vector<double>& a, int resamples, std::uint64_t seed, double alpha) {
    MedianInterval r;
    if (a.empty() || resamples <= 0) return r;
    r.median = median(a);
    std::mt19937_64 rng(seed);
    std::vector<double> ra(a.size()), medians;
    medians.reserve(static_cast<size_t>(resamples));
    for (int i = 0; i < resamples; ++i) {
        for (auto& v : ra) v = a[draw(rng, a.size())];
        medians.push_back(medianInPlace(ra));
    }
    std::sort(medians.begin(), medians.end());
    r.low = percentile(medians, alpha / 2.0);
    r.high = percentile(medians, 1.0 - alpha / 2.0);
    r.resamples = resamples;
    return r;
}

RatioInterval bootstrapRatioOfMedians(const std::vector<double>& a, const std::vector<double>& b, int resamples,
                                      std::uint64_t seed, double alpha) {
    RatioInterval r;
    if (a.empty() || b.empty() || resamples <= 0) return r;
    const double mb = median(b);
    if (!(mb > 0.0)) return r;
    r.ratio = median(a) / mb;
    std::mt19937_64 rng(seed);
    std::vector<double> ra(a.size()), rb(b.size()), ratios;
    ratios.reserve(static_cast<size_t>(resamples));
    for (int i = 0; i < resamples; ++i) {
        for (auto& v : ra) v = a[draw(rng, a.size())];
        for (auto& v : rb) v = b[draw(rng, b.size())];
        const double den = medianInPlace(rb);
        if (den > 0.0) ratios.push_back(medianInPlace(ra) / den);
    }
    if (ratios.empty()) return r;
    std::sort(ratios.begin(), ratios.end());
    r.low = percentile(ratios, alpha / 2.0);
    r.high = percentile(ratios, 1.0 - alpha / 2.0);
    r.resamples = static_cast<int>(ratios.size());
    return r;
}

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
        differences.push_back(medianInPlace(ra) - medianInPlace(rb));
    }
    std::sort(differences.begin(), differences.end());
    r.low = percentile(differences, alpha / 2.0);
    r.high = percentile(differences, 1.0 - alpha / 2.0);
    r.resamples = resamples;
    return r;
}

Interval bootstrapGroupMean(const std::vector<double>& sums, const std::vector<double>& weights, int resamples,
                            std::uint64_t seed, double alpha) {
    Interval r;
    const size_t n = std::min(sums.size(), weights.size());
    if (n == 0 || resamples <= 0) return r;
    std::mt19937_64 rng(seed);
    std::vector<double> means;
    means.reserve(static_cast<size_t>(resamples));
    for (int i = 0; i < resamples; ++i) {
        double s = 0.0, w = 0.0;
        for (size_t k = 0; k < n; ++k) {
            const size_t j = draw(rng, n);
            s += sums[j];
            w += weights[j];
        }
        if (w > 0.0) means.push_back(s / w);
    }
    if (means.empty()) return r;
    std::sort(means.begin(), means.end());
    r.low = percentile(means, alpha / 2.0);
    r.high = percentile(means, 1.0 - alpha / 2.0);
    r.resamples = static_cast<int>(means.size());
    return r;
}

}  // namespace dw
