// The window's guard against an AOV frame that would take minutes (issue 22,
// ui/AovCostGuard): a state over AovCostEstimate's limits is put back to the
// last good one with the warning as the banner; confirmed, it renders and is
// kept until the knobs change; a state under the limits passes.
#include <gtest/gtest.h>

#include "tests/gui/HeadlessImGui.h"
#include "tests/support/TestSupport.h"
#include "ui/ParetoPanel.h"
#include "ui/TimingsPanel.h"
#include "ui/Widgets.h"
#include "ui/ViewportComposer.h"
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

// The estimate is taken at the size the frame renders at (the viewport
// panel's size times the resolution scale), from the first frame on, and again
// whenever that size changes: AOV at radius 1 on the courtyard passes at
// 160x90 (0.12 million at 80x45) and is refused at 2560x1440 (about 31
// million at 1280x720). A confirmation holds at its size and smaller ones.
TEST(AovCostGuard, EstimatesAtTheSizeTheFrameRendersAtAndAgainWhenItChanges) {
    auto session = test::makeSession(32, 32);
    ui::UiState state;
    session->loadScene("default", state.run);
    KnobRegistry& k = session->knobs();
    auto method = [&] { return k.spec(*k.find("ao.method")).choices[static_cast<size_t>(k.value(*k.find("ao.method")))]; };
    k.setFromString("ao.method", "aov");

    // The first frame: nothing rendered yet (renderSize 0x0), the panel wants 2560x1440.
    {
        ui::AovCostGuard guard;
        state.renderSize = {0, 0};
        state.wantedSize = {2560, 1440};
        guard.beforeFrame(state, *session);
        EXPECT_TRUE(guard.refusing());
        EXPECT_NE(guard.message().find("at 1280x720"), std::string::npos) << guard.message();
        EXPECT_EQ(method(), "ssao");
    }

    // Passes at 160x90; the same knobs, camera and scene at 2560x1440 are estimated again and refused.
    k.setFromString("ao.method", "aov");
    ui::AovCostGuard guard;
    state.renderSize = {160, 90};
    state.wantedSize = {160, 90};
    guard.beforeFrame(state, *session);
    EXPECT_FALSE(guard.refusing());
    EXPECT_EQ(method(), "aov");
    state.wantedSize = {2560, 1440};
    guard.beforeFrame(state, *session);
    EXPECT_TRUE(guard.refusing());
    EXPECT_NE(guard.message().find("at 1280x720"), std::string::npos) << guard.message();
    EXPECT_EQ(method(), "ssao");

    // Confirmed at 2560x1440: kept there and at a smaller size; a larger one asks again.
    guard.confirm(state, *session);
    EXPECT_EQ(method(), "aov");
    guard.beforeFrame(state, *session);
    EXPECT_FALSE(guard.refusing());
    state.wantedSize = {1280, 720};
    guard.beforeFrame(state, *session);
    EXPECT_FALSE(guard.refusing());
    EXPECT_EQ(method(), "aov");
    state.wantedSize = {3840, 2160};
    guard.beforeFrame(state, *session);
    EXPECT_TRUE(guard.refusing());
    EXPECT_EQ(method(), "ssao");

    // The resolution scale is part of the size: quarter of 2560x1440 is 640x360, 2 million at 320x180.
    guard.dismiss(state);
    k.setFromString("ao.method", "aov");
    state.wantedSize = {2560, 1440};
    state.viewport.resolution = ui::ResolutionScale::Quarter;
    guard.beforeFrame(state, *session);
    EXPECT_FALSE(guard.refusing());
    EXPECT_EQ(method(), "aov");
}

// The guard's own undo is no change of the user's: the timings panel shows
// the change before the refused one, and forgets a refused change (measure
// would render the refused state).
TEST(AovCostGuard, PuttingTheKnobsBackIsNoMeasurableChange) {
    auto session = test::makeSession(32, 32);
    ui::UiState state;
    session->loadScene("default", state.run);
    state.renderSize = {160, 90};
    test::HeadlessImGui imgui;
    ui::TimingsPanel panel;
    ui::AovCostGuard guard;
    bool open = true;
    KnobRegistry& k = session->knobs();
    // The window's order: the guard, then the panels (where the user edits).
    auto frame = [&] {
        guard.beforeFrame(state, *session);
        imgui.frame([&] { panel.draw("GPU timings", &open, state, *session); });
    };
    frame();
    k.setFromString("ssao.samples", "64");
    frame();
    ASSERT_TRUE(panel.change);
    EXPECT_EQ(panel.change->what, "ssao.samples 16 -> 64");

    // A change the guard lets through is the user's.
    k.setFromString("ao.method", "aov");
    frame();
    ASSERT_TRUE(panel.change);
    EXPECT_EQ(panel.change->what, "ao.method ssao -> aov");

    // Refused (radius 20): committed in the panel as the user's, then put back by the guard.
    k.setFromString("aov.radius", "20");
    imgui.frame([&] { panel.draw("GPU timings", &open, state, *session); });
    ASSERT_TRUE(panel.change);
    EXPECT_EQ(panel.change->what, "aov.radius 1 -> 20");
    frame();
    EXPECT_TRUE(guard.refusing());
    EXPECT_EQ(k.value(*k.find("aov.radius")), 1.0);
    EXPECT_FALSE(panel.change) << panel.change->what;  // neither "aov.radius 20 -> 1" nor the refused change
    panel.startMeasure(state, *session);
    EXPECT_FALSE(state.measure.active());
    frame();
    EXPECT_FALSE(panel.change);

    // Refused in the same frame it was set (a scripted --set): the earlier change stays, and no undo shows.
    guard.dismiss(state);
    k.setFromString("aov.radius", "2");
    frame();
    ASSERT_TRUE(panel.change);
    EXPECT_EQ(panel.change->what, "aov.radius 1 -> 2");
    k.setFromString("aov.radius", "20");
    frame();
    EXPECT_TRUE(guard.refusing());
    ASSERT_TRUE(panel.change);
    EXPECT_EQ(panel.change->what, "aov.radius 1 -> 2");
    frame();
    EXPECT_EQ(panel.change->what, "aov.radius 1 -> 2");
}

// The A/B split's preset side renders a knob state of its own: over the
// limits (AOV1 on the spheres: radius 1 world unit, about 2600 a pixel) B
// is not rendered, the numbers line says why, and A renders as before.
TEST(AovCostGuard, TheAbPresetSideOverTheLimitIsRefusedAndAIsKept) {
    auto session = test::makeSession(32, 18);
    ui::UiState state;
    session->loadScene("spheres", state.run);
    state.wantedSize = {32, 18};
    state.ab.enabled = true;
    state.ab.source = ui::AbSource::Preset;
    state.ab.preset = "AOV1";
    ui::ViewportComposer composer(*session);
    const std::uint64_t before = state.framesRendered;
    composer.render(state);
    EXPECT_GT(state.framesRendered, before);
    EXPECT_NE(state.ab.unavailable.find("preset 'AOV1' not rendered: aov: about "), std::string::npos)
        << state.ab.unavailable;
    EXPECT_NE(state.ab.unavailable.find("a frame on llvmpipe"), std::string::npos) << state.ab.unavailable;
    // A's knobs are untouched.
    const KnobRegistry& k = session->knobs();
    EXPECT_EQ(k.spec(*k.find("ao.method")).choices[static_cast<size_t>(k.value(*k.find("ao.method")))], "ssao");
    // The same preset on the courtyard at this size is under the limits: B renders.
    session->loadScene("default", state.run);
    composer.render(state);
    EXPECT_EQ(state.ab.unavailable.find("not rendered"), std::string::npos) << state.ab.unavailable;
}

// The Pareto panel's quick sweep renders knob states of its own, which the
// live view's guard never sees: on the spheres at radius 1 (about 2600
// volume fragments a pixel) a sweep of ao.method has one value, aov, over
// the limits. The sweep asks before it renders anything (the message in the
// panel and as the banner, the knobs untouched); *sweep anyway* starts it; a
// sweep whose values are all under the limits starts at once.
TEST(AovCostGuard, AQuickSweepWithAValueOverTheLimitAsksFirstAndStartsWhenConfirmed) {
    auto session = test::makeSession(32, 18);
    ui::UiState state;
    session->loadScene("spheres", state.run);
    session->render({{"final"}});
    const KnobRegistry& k = session->knobs();
    auto method = [&] { return k.spec(*k.find("ao.method")).choices[static_cast<size_t>(k.value(*k.find("ao.method")))]; };
    ASSERT_EQ(method(), "ssao");
    const size_t methods = k.spec(*k.find("ao.method")).choices.size();

    const auto over = ui::ParetoPanel::overAovCost("ao.method", *session, 32, 18);
    ASSERT_EQ(over.size(), 1u);
    EXPECT_EQ(over[0].first, "aov");
    EXPECT_NE(over[0].second.find("aov: about "), std::string::npos) << over[0].second;
    // A sweep that touches no AOV state is under the limits.
    EXPECT_TRUE(ui::ParetoPanel::overAovCost("gbuffer.normal_encoding", *session, 32, 18).empty());

    ui::ParetoPanel panel;
    panel.againstCurrent = true;  // the reference's question is Gui.AQuickSweepWithoutACpuReference...
    EXPECT_FALSE(panel.startSweep("ao.method", state, *session));
    EXPECT_FALSE(state.sweep.running());
    EXPECT_EQ(panel.askedKnob, "ao.method");
    EXPECT_NE(panel.askedCost.find("1 of " + std::to_string(methods) + " values over the AOV cost limit (aov)"),
              std::string::npos)
        << panel.askedCost;
    EXPECT_NE(panel.askedCost.find("ao.method=aov: aov: about "), std::string::npos) << panel.askedCost;
    ASSERT_NE(state.log.banner(), nullptr);
    EXPECT_NE(state.log.banner()->text.find("quick sweep of ao.method not started"), std::string::npos)
        << state.log.banner()->text;
    EXPECT_EQ(method(), "ssao");

    // The panel shows the question; a click on *sweep anyway* starts the sweep.
    test::HeadlessImGui imgui(ImVec2(800, 600));
    bool open = true;
    auto draw = [&] {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(800, 600));
        panel.draw("Pareto", &open, state, *session);
    };
    imgui.frame(draw);
    imgui.frame(draw);
    const auto& items = ui::drawnItems();
    ASSERT_TRUE(items.count("pareto.sweep_anyway"));
    const ui::DrawnItem& b = items.at("pareto.sweep_anyway");
    EXPECT_EQ(b.frame, ImGui::GetFrameCount());
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(b.x + b.w * 0.5f, b.y + b.h * 0.5f);
    imgui.frame(draw);
    io.MouseDown[0] = true;
    imgui.frame(draw);
    io.MouseDown[0] = false;
    imgui.frame(draw);
    EXPECT_TRUE(state.sweep.running()) << panel.error << " | " << panel.askedCost;
    EXPECT_EQ(state.sweep.knob(), "ao.method");
    EXPECT_TRUE(panel.askedCost.empty());
    EXPECT_EQ(state.log.banner(), nullptr);
    state.sweep.cancel();

    // Under the limits: no question.
    EXPECT_TRUE(panel.startSweep("gbuffer.normal_encoding", state, *session));
    EXPECT_TRUE(state.sweep.running());
    EXPECT_TRUE(panel.askedCost.empty());
    state.sweep.cancel();
}
