// The bootstrap interval of a difference of medians (renderer/metrics/Bootstrap),
// which the workbench's A/B view states for the two sides' GPU frame times.
#include <gtest/gtest.h>

#include "renderer/metrics/Bootstrap.h"

using namespace dw;

TEST(DifferenceInterval, MediansDifferenceWithAnIntervalAroundIt) {
    const std::vector<double> a = {10, 11, 12, 13, 14, 12, 11, 13}, b = {5, 6, 7, 8, 9, 7, 6, 8};
    const DifferenceInterval d = bootstrapDifferenceOfMedians(a, b);
    ASSERT_TRUE(d.valid());
    EXPECT_DOUBLE_EQ(d.difference, 12.0 - 7.0);
    EXPECT_LE(d.low, d.difference);
    EXPECT_GE(d.high, d.difference);
    EXPECT_GT(d.low, 0.0);   // the sides do not overlap: the interval excludes 0
    EXPECT_LT(d.high, 9.0);  // and stays within the extremes' difference (14 - 5)
    // Seeded: the same samples give the same interval; swapped sides negate it.
    const DifferenceInterval again = bootstrapDifferenceOfMedians(a, b);
    EXPECT_EQ(again.low, d.low);
    EXPECT_EQ(again.high, d.high);
    const DifferenceInterval swapped = bootstrapDifferenceOfMedians(b, a);
    EXPECT_DOUBLE_EQ(swapped.difference, -d.difference);
}

TEST(DifferenceInterval, EqualSidesStraddleZeroAndAnEmptySideIsInvalid) {
    const std::vector<double> a = {3, 5, 4, 6, 5, 4}, b = {5, 4, 6, 3, 4, 5};
    const DifferenceInterval d = bootstrapDifferenceOfMedians(a, b);
    EXPECT_DOUBLE_EQ(d.difference, 0.0);
    EXPECT_LE(d.low, 0.0);
    EXPECT_GE(d.high, 0.0);
    EXPECT_FALSE(bootstrapDifferenceOfMedians({}, b).valid());
    EXPECT_FALSE(bootstrapDifferenceOfMedians(a, {}).valid());
}
