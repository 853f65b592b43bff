// The fire scene: its flame-particle lights move with the frame index, so two
// frames light the scene differently, and nothing turns into NaN.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/passes/FlamesPass.h"
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

// Issue 36 part 4: the flames pass adds exactly flames.result into the
// L-buffer (the same frame with flames.enabled=false differs by it), the
// sprites are not empty, and the final image changes where they are.
TEST(FireScene, FlamesAreAddedIntoTheLBufferAndShowInTheFinalImage) {
    FloatImage lbuffer[2], image[2], flames;
    for (int on = 0; on < 2; ++on) {
        auto s = test::makeSession(96, 54);  // each session starts at frame 0: the same pose of the fire
        s->loadScene("fire");
        s->knobs().setFromString("flames.enabled", on ? "true" : "false");
        s->render({{"lbuffer", "final", on ? "flames.result" : "lbuffer"}});
        lbuffer[on] = s->readRaw("lbuffer");
        image[on] = s->readRaw("final");
        if (on) flames = s->readRaw("flames.result");
    }
    int lit = 0;
    double worstExcess = 0.0, finalChange = 0.0;
    for (int y = 0; y < flames.height; ++y)
        for (int x = 0; x < flames.width; ++x) {
            const bool flame = flames.at(x, y, 0) > 0.02f;
            lit += flame;
            for (int c = 0; c < 3; ++c) {
                const double f = flames.at(x, y, c), added = lbuffer[1].at(x, y, c) - lbuffer[0].at(x, y, c);
                // flames.result is RGBA16F, summed over up to dozens of overlapping sprites:
                // each sum rounds to 11 bits, the L-buffer's (RGBA32F) does not.
                worstExcess = std::max(worstExcess, std::abs(added - f) - (1e-2 * std::abs(f) + 1e-4));
                if (flame) finalChange = std::max(finalChange, std::abs(static_cast<double>(image[1].at(x, y, c)) - image[0].at(x, y, c)));
            }
        }
    EXPECT_GT(lit, 20);
    EXPECT_LE(worstExcess, 0.0);
    EXPECT_GT(finalChange, 0.05);
    EXPECT_EQ(test::stats(flames, 0).nonFinite, 0);
}

// The temperature ramp: Planck's law at 610, 550 and 465 nm, worked by hand
// for 2000 K (green / red = (610/550)^5 e^(c2/(0.61 um T) - c2/(0.55 um T))
// = 0.461, blue / red = 0.098) and 1000 K (0.127, 0.0025); cooler is redder.
TEST(FireScene, FlameColourFollowsABlackBodyAsTheParticleCools) {
    const glm::vec3 hot = blackbodyColour(flameTemperature(0.0f)), cold = blackbodyColour(flameTemperature(1.0f));
    EXPECT_FLOAT_EQ(hot.r, 1.0f);
    EXPECT_NEAR(hot.g, 0.461, 0.005);
    EXPECT_NEAR(hot.b, 0.098, 0.003);
    EXPECT_NEAR(cold.g, 0.127, 0.003);
    EXPECT_NEAR(cold.b, 0.0025, 0.0005);
    float last = 1.0f;
    for (float age = 0.1f; age <= 1.0f; age += 0.1f) {
        const glm::vec3 c = blackbodyColour(flameTemperature(age));
        EXPECT_LT(c.g, last) << age;
        last = c.g;
    }
}
