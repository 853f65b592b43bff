#include <gtest/gtest.h>

#include "renderer/graph/PassTimer.h"

using namespace dw;

TEST(TimingStats, MedianMeanMinMax) {
    const TimingStats odd = computeStats({5.0f, 1.0f, 3.0f});
    EXPECT_FLOAT_EQ(odd.median, 3.0f);
    EXPECT_FLOAT_EQ(odd.mean, 3.0f);
    EXPECT_FLOAT_EQ(odd.min, 1.0f);
    EXPECT_FLOAT_EQ(odd.max, 5.0f);
    const TimingStats even = computeStats({4.0f, 1.0f, 2.0f, 100.0f});
    EXPECT_FLOAT_EQ(even.median, 3.0f);  // robust to the outlier
    EXPECT_EQ(even.count, 4);
    EXPECT_EQ(computeStats({}).count, 0);
}
