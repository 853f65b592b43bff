#pragma once
// How sure a ratio of two medians is, by the percentile bootstrap (Efron):
// resample each side's frames with replacement, take the ratio of the
// resamples' medians, and read the 2.5th and 97.5th percentiles of those
// ratios. `bench` uses it for "configuration / baseline" frame times. The
// resampling is seeded, so the same samples always give the same interval.
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace dw {

// The fewest samples per side from which the experiment records and
// `replay` state an interval of a median (or of a ratio or difference of
// medians). Below 6 no interval of a median reaches 95% from the samples
// alone: the widest, the range of n samples, holds the median with
// probability 1 - 2^(1-n) (75% for 3, 94% for 5, 97% for 6), and a bootstrap
// of so few values only repeats them. Fewer frames are recorded and printed
// as kTooFewForInterval, the median alone.
constexpr std::size_t kMinIntervalSamples = 6;
inline const std::string kTooFewForInterval = "too few frames for an interval";
inline bool enoughForInterval(std::size_t samples) { return samples >= kMinIntervalSamples; }

struct RatioInterval {
    double ratio = 0.0;  // median(a) / median(b) of the samples themselves
    double low = 0.0, high = 0.0;
    int resamples = 0;
    bool valid() const { return resamples > 0; }
};

// The median of a series with a (1 - alpha) percentile interval (the
// experiment records' "median and interval" per timing series, `tradeoff`'s
// frame time interval).
struct MedianInterval {
    double median = 0.0, low = 0.0, high = 0.0;
    int resamples = 0;
    bool valid() const { return resamples > 0; }
};

double median(std::vector<double> values);

// A resample's index in [0, n), n > 0: the same on every platform (std::uniform_int_distribution is not).
std::size_t bootstrapIndex(std::mt19937_64& rng, std::size_t n);

// median(a) with a (1 - alpha) percentile bootstrap interval; invalid when `a` is empty.
MedianInterval bootstrapMedian(const std::vector<double>& a, int resamples = 2000, std::uint64_t seed = 12345,
                               double alpha = 0.05);

// median(a) / median(b) with a (1 - alpha) percentile interval from
// `resamples` bootstrap draws. Invalid (resamples 0) when a side is empty or
// b's median is not positive.
RatioInterval bootstrapRatioOfMedians(const std::vector<double>& a, const std::vector<double>& b, int resamples = 2000,
                                      std::uint64_t seed = 12345, double alpha = 0.05);

// median(a) - median(b) with a (1 - alpha) percentile interval, the
// companion of the ratio: the workbench's A/B view states "A - B = 0.8 ms
// [0.5, 1.1]" with it. Invalid (resamples 0) when a side is empty.
struct DifferenceInterval {
    double difference = 0.0;  // median(a) - median(b) of the samples themselves
    double low = 0.0, high = 0.0;
    int resamples = 0;
    bool valid() const { return resamples > 0; }
};
DifferenceInterval bootstrapDifferenceOfMedians(const std::vector<double>& a, const std::vector<double>& b,
                                                int resamples = 2000, std::uint64_t seed = 12345, double alpha = 0.05);

// A percentile interval of a statistic of resampled data.
struct Interval {
    double low = 0.0, high = 0.0;
    int resamples = 0;
    bool valid() const { return resamples > 0; }
};

// The weighted mean sum(sums) / sum(weights) over groups resampled with
// replacement (group i: sums[i], weights[i]; e.g. a tile's summed per-pixel
// error and its pixel count, or one camera's error with weight 1): its
// (1 - alpha) percentile interval. Invalid when empty or all weights are 0.
Interval bootstrapGroupMean(const std::vector<double>& sums, const std::vector<double>& weights, int resamples = 2000,
                            std::uint64_t seed = 12345, double alpha = 0.05);

}  // namespace dw
