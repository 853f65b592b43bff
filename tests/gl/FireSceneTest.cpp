// The fire scene: its flame-particle lights move with the frame index, so two
// frames light the scene differently, and nothing turns into NaN.
#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

using namespace dw;

TEST(FireScene, TwoFrameIndicesGiveDifferentLBuffersWithoutNaN) {
    auto s = test::makeSession(96, 54);
    s->loadScene("fire");
    const size_t first = s->scene().flames.firstLight;
    FloatImage frames[2];
    glm::vec3 lightAt[2];
    int k = 0;
    for (std::uint64_t f = 0; f <= 6; ++f) {
        const FrameReport r = s->render({{"lbuffer"}});
        EXPECT_EQ(r.frameIndex, f);
        if (f != 0 && f != 6) continue;
        frames[k] = s->readRaw("lbuffer");
        lightAt[k] = s->scene().lights[first].position;
        ++k;
    }
    EXPECT_NE(lightAt[0], lightAt[1]);
    for (const auto& L : frames)
        for (int c = 0; c < 3; ++c) {
            const test::ChannelStats st = test::stats(L, c);
            EXPECT_EQ(st.nonFinite, 0) << c;
            EXPECT_GT(st.max, 0.0) << c;
        }
    EXPECT_GT(test::maxAbsDifference(frames[0], frames[1], 3), 1e-3);
}
