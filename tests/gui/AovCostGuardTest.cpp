// The window's guard against an AOV frame that would take minutes (issue 22,
// ui/AovCostGuard): a state over AovCostEstimate's limits is put back to the
// last good one with the warning as the banner; confirmed, it renders and is
// kept until the knobs change; a state under the limits passes.
#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"
#include "ui/AovCostGuard.h"
#include "ui/UiState.h"

using namespace dw;

TEST(AovCostGuard, RefusesAStateOverTheLimitKeepsTheLastGoodOneAndRendersItWhenConfirmed) {
    auto session = test::makeSession(32, 32);
    ui::UiState state;
    session->loadScene("default", state.run);
    state.renderSize = {160, 90};
    KnobRegistry& k = session->knobs();
    ui::AovCostGuard guard;
    auto method = [&] { return k.spec(*k.find("ao.method")).choices[static_cast<size_t>(k.value(*k.find("ao.method")))]; };
    auto radius = [&] { return k.value(*k.find("aov.radius")); };

    // AOV at radius 1 on the courtyard: about 34 a pixel, 0.12 million at 80x45 (half size). Passes.
    k.setFromString("ao.method", "aov");
    guard.beforeFrame(state, *session);
    EXPECT_EQ(method(), "aov");
    EXPECT_FALSE(guard.refusing());
    EXPECT_EQ(state.log.banner(), nullptr);

    // Radius 20: every volume covers most of the screen. Put back to radius 1.
    k.setFromString("aov.radius", "20");
    guard.beforeFrame(state, *session);
    EXPECT_TRUE(guard.refusing());
    EXPECT_EQ(method(), "aov");
    EXPECT_EQ(radius(), 1.0);
    ASSERT_NE(state.log.banner(), nullptr);
    EXPECT_NE(state.log.banner()->text.find("aov: about "), std::string::npos) << state.log.banner()->text;
    EXPECT_NE(state.log.banner()->text.find("lower aov.radius"), std::string::npos);
    EXPECT_NE(guard.message().find("at aov.radius 20 world units"), std::string::npos) << guard.message();

    // Confirmed: the refused state comes back and stays, frame after frame.
    guard.confirm(state, *session);
    EXPECT_FALSE(guard.refusing());
    EXPECT_EQ(state.log.banner(), nullptr);
    EXPECT_EQ(radius(), 20.0);
    guard.beforeFrame(state, *session);
    EXPECT_EQ(radius(), 20.0);
    EXPECT_FALSE(guard.refusing());

    // Another state over the limit is asked about again, and put back to the
    // last state under the limit (radius 1), not to the confirmed one.
    k.setFromString("aov.radius", "19");
    guard.beforeFrame(state, *session);
    EXPECT_TRUE(guard.refusing());
    EXPECT_EQ(method(), "aov");
    EXPECT_EQ(radius(), 1.0);
    guard.dismiss(state);
    EXPECT_FALSE(guard.refusing());
    EXPECT_EQ(radius(), 1.0);

    // With no good state behind it (a new scene opened straight into AOV at
    // radius 20), ao.method goes back to its default.
    ui::AovCostGuard fresh;
    k.setFromString("aov.radius", "20");
    fresh.beforeFrame(state, *session);
    EXPECT_TRUE(fresh.refusing());
    EXPECT_EQ(method(), "ssao");
}
