#pragma once
// How sure a difference of two medians is, by the percentile bootstrap
// (Efron), the companion of Bootstrap.h's ratio: resample each side's values
// with replacement, take median(a*) - median(b*), read the 2.5th and 97.5th
// percentiles. The workbench's A/B view states "A - B = 0.8 ms [0.5, 1.1]"
// with it. Seeded: the same samples always give the same interval.
#include <cstdint>
#include <vector>

namespace dw {

struct DifferenceInterval {
    double difference = 0.0;  // median(a) - median(b) of the samples themselves
    double low = 0.0, high = 0.0;
    int resamples = 0;
    bool valid() const { return resamples > 0; }
};

// Invalid (resamples 0) when a side is empty.
DifferenceInterval bootstrapDifferenceOfMedians(const std::vector<double>& a, const std::vector<double>& b,
                                                int resamples = 2000, std::uint64_t seed = 12345, double alpha = 0.05);

}  // namespace dw
