// Issue 34 part 3 in the window: the Pareto panel's *fit budget* sweeps the
// speed/quality knobs about the current settings (as tradeoff --knobs
// speed/quality), applies the budget's pick, measures it against the previous
// settings with the cost of a change, and undoes it in one click; a budget
// nothing fits applies nothing and says so; cancelling leaves the settings
// untouched; a budget of 0, NaN or below 0 and an unknown pass are refused on
// screen before anything renders. Driven as a person would, at a tiny size.
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <thread>

#include "renderer/passes/ReferencePass.h"
#include "tests/gui/HeadlessImGui.h"
#include "tests/gui/ParetoDriver.h"
#include "tests/support/TestSupport.h"
#include "ui/ParetoPanel.h"
#include "ui/ReferenceControls.h"
#include "ui/TimingsPanel.h"
#include "ui/Widgets.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

std::string allKnobs(RenderSession& session) {
    std::string s;
    for (int id = 0; id < static_cast<int>(session.knobs().size()); ++id)
        s += session.knobs().spec(id).name + "=" + session.knobs().format(id) + ",";
    return s;
}

std::string knobText(RenderSession& session, const std::string& name) {
    return session.knobs().format(*session.knobs().find(name));
}

bool drawnNow(const std::string& name) {
    const auto& items = ui::drawnItems();
    return items.count(name) && items.at(name).frame == ImGui::GetFrameCount();
}

// Steps the fit's sweep to its end as the frame loop does (one frame a step;
// with `viewFrames`, the view's own frame after each, as the window renders it).
void runFit(ui::UiState& state, RenderSession& session, bool viewFrames = false) {
    int steps = 0;
    while (state.fitBudget.step(session)) {
        ASSERT_LT(++steps, 20000);
        if (viewFrames) session.render({{"final"}});
    }
}

}  // namespace

// Every point kept its 6 counted frames and intervals; the pick is the least error of the sweep.
static void expectPickIsTheLeastError(const TradeoffTable& table, int point) {
    double least = std::numeric_limits<double>::infinity(), picked = -1.0;
    for (const TradeoffRow& r : table.rows) {
        least = std::min(least, r.error);
        if (r.point == point) picked = r.error;
        EXPECT_EQ(r.frames, 6) << "point " << r.point;  // none lost among the view's own frames
        EXPECT_LE(r.errorLo, r.error);
        EXPECT_GE(r.timeMsHi, r.timeMs);
    }
    EXPECT_EQ(picked, least);
}

// The point is named by the one value it changes, not by all of the sweep's axes.
static void expectNamedByOneValue(const std::string& l) {
    const size_t open = l.find('('), close = l.find(')');
    ASSERT_LT(open, close) << l;
    EXPECT_EQ(std::count(l.begin() + static_cast<long>(open), l.begin() + static_cast<long>(close), '='), 1) << l;
}

TEST(FitBudget, AppliesThePickMeasuresTheChangeAndUndoes) {
    const fs::path cache = test::tempDir() / "fit-budget-reference-cache";
    fs::remove_all(cache);
    setenv("DW_REFERENCE_CACHE", cache.string().c_str(), 1);
    auto session = test::makeSession(32, 18);
    ui::UiState state;
    session->loadScene("default", state.run);
    session->render({{"final"}});
    const std::string before = allKnobs(*session);
    test::HeadlessImGui imgui(ImVec2(800, 900));
    ui::ParetoPanel panel;
    ui::ReferenceControls reference;
    reference.aoRays = 8;
    test::ParetoDriver driver{imgui, state, *session, panel, reference, ImVec2(800, 900)};

    // A generous budget: every point fits, so the pick is the least error of the sweep.
    panel.budgetMs = 1e6;
    driver.click("pareto.fit_budget");
    EXPECT_TRUE(panel.fit.waitingForReference) << panel.fit.message;  // no reference shown: traced first
    for (int i = 0; i < 6000 && !state.fitBudget.running(); ++i) {
        driver.frame();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(state.fitBudget.running()) << panel.fit.message;
    EXPECT_EQ(state.fitBudget.baselineName(), "the CPU reference");
    // The default aa.method=fxaa is an effect the reference's final image has not: said before the pick.
    EXPECT_EQ(panel.fit.referenceNote.rfind("note: the reference's final image has no", 0), 0u) << panel.fit.referenceNote;
    EXPECT_NE(panel.fit.referenceNote.find("aa.method"), std::string::npos) << panel.fit.referenceNote;
    driver.frame();
    EXPECT_TRUE(drawnNow("pareto.fit_progress"));
    // The timings panel watches the knobs as in the window (its committed values: the previous settings).
    ui::TimingsPanel timings;
    bool timingsOpen = true;
    auto drawTimings = [&] { imgui.frame([&] { timings.draw("GPU timings", &timingsOpen, state, *session); }); };
    drawTimings();
    // The camera moved while the sweep runs: every point is still rendered from where it started.
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(state.fitBudget.step(*session)) << state.fitBudget.error();
    const glm::vec3 moved = session->camera().position + glm::vec3(0.5f, 0.0f, 0.0f);
    session->camera().position = moved;
    runFit(state, *session, true);
    ASSERT_TRUE(state.fitBudget.done()) << state.fitBudget.error();
    EXPECT_EQ(allKnobs(*session), before) << "the sweep changed the settings";
    EXPECT_EQ(session->camera().position, moved);
    drawTimings();
    driver.frame();

    // The pick is applied: every knob of its point holds its value, and it is the least error of the sweep.
    const BudgetPick& pick = state.fitBudget.pick();
    ASSERT_GE(pick.point, 0) << (pick.lines.empty() ? "" : pick.lines[0]);
    EXPECT_EQ(pick.fitting, static_cast<int>(state.fitBudget.points()));
    expectPickIsTheLeastError(state.fitBudget.table(), pick.point);
    for (const std::string& a : state.fitBudget.assignmentsOf(pick.point)) {
        const size_t eq = a.find('=');
        EXPECT_EQ(knobText(*session, a.substr(0, eq)), a.substr(eq + 1)) << a;
    }
    ASSERT_TRUE(panel.fit.change) << "the pick is the current settings: " << panel.fit.applied;
    EXPECT_NE(allKnobs(*session), before);
    ASSERT_FALSE(panel.fit.pickLines.empty());
    EXPECT_EQ(panel.fit.pickLines[0].rfind("pick: point " + std::to_string(pick.point), 0), 0u) << panel.fit.pickLines[0];
    EXPECT_NE(panel.fit.pickLines[0].find("flip"), std::string::npos) << panel.fit.pickLines[0];
    expectNamedByOneValue(panel.fit.pickLines[0]);
    EXPECT_NE(panel.fit.pickLines[0].find("frame time"), std::string::npos) << panel.fit.pickLines[0];
    EXPECT_TRUE(drawnNow("pareto.fit_pick") && drawnNow("pareto.fit_applied") && drawnNow("pareto.fit_undo"));
    // The sweep is the table on show, its pick ringed.
    EXPECT_TRUE(panel.tableIsFit);
    for (const TradeoffRow& r : panel.table.rows)
        if (r.point == pick.point) {
            EXPECT_EQ(r.pick, "pick");
        }

    // Then the cost of the change from the previous settings, measured and shown with its interval.
    ASSERT_TRUE(panel.fit.measuring);
    ASSERT_TRUE(state.measure.active());
    EXPECT_EQ(state.measure.change().what, panel.fit.change->what);
    driver.frame();
    EXPECT_TRUE(drawnNow("pareto.fit_measure_progress"));
    int steps = 0;
    while (state.measure.step(*session)) ASSERT_LT(++steps, 400);
    driver.frame();
    ASSERT_TRUE(panel.fit.verdict) << panel.fit.measureStatus;
    const PassVerdict* frame = panel.fit.verdict->find("frame");
    ASSERT_NE(frame, nullptr);
    EXPECT_TRUE(frame->ratio.valid());
    EXPECT_LE(frame->ratio.low, frame->ratio.high);
    EXPECT_TRUE(drawnNow("pareto.fit_measured.frame"));
    // The timings panel takes the applied change as its own and keeps the verdict measured.
    drawTimings();
    ASSERT_TRUE(timings.change);
    EXPECT_EQ(timings.change->what, panel.fit.change->what);
    EXPECT_EQ(state.measure.state(), ChangeMeasurement::State::Done);

    // One undo: the settings before the fit are back.
    driver.click("pareto.fit_undo");
    EXPECT_EQ(allKnobs(*session), before);
    EXPECT_FALSE(panel.fit.change);
    unsetenv("DW_REFERENCE_CACHE");
}

TEST(FitBudget, AnImpossibleBudgetOrACancelAppliesNothingAndABadBudgetIsRefusedOnScreen) {
    auto session = test::makeSession(32, 18);
    ui::UiState state;
    session->loadScene("default", state.run);
    session->render({{"final"}});
    const std::string before = allKnobs(*session);
    test::HeadlessImGui imgui(ImVec2(700, 800));
    ui::ParetoPanel panel;
    ui::ReferenceControls reference;
    test::ParetoDriver driver{imgui, state, *session, panel, reference, ImVec2(700, 800)};
    panel.againstCurrent = true;  // no CPU reference needed here

    // A budget of 0, NaN or below 0, or a pass the pipeline lacks: one line on screen, nothing started or traced.
    for (double bad : {0.0, std::numeric_limits<double>::quiet_NaN(), -3.0}) {
        panel.budgetMs = bad;
        driver.click("pareto.fit_budget");
        EXPECT_FALSE(state.fitBudget.running());
        EXPECT_FALSE(state.requestReference);
        EXPECT_EQ(panel.fit.message.rfind("fit budget not started: --budget-ms must be a number above 0 and at most "
                                          "1000000000 (GPU milliseconds), got '",
                                          0),
                  0u)
            << panel.fit.message;
        EXPECT_TRUE(drawnNow("pareto.fit_message"));
    }
    EXPECT_NE(panel.fit.message.find("got '-3'"), std::string::npos) << panel.fit.message;
    panel.budgetMs = 10.0;
    std::snprintf(panel.fit.time, sizeof(panel.fit.time), "lighting+bogus");
    driver.click("pareto.fit_budget");
    EXPECT_FALSE(state.fitBudget.running());
    EXPECT_NE(panel.fit.message.find("no pass 'bogus'"), std::string::npos) << panel.fit.message;
    std::snprintf(panel.fit.time, sizeof(panel.fit.time), "frame");

    // Cancelled part-way: the settings untouched, nothing applied, said so.
    driver.click("pareto.fit_budget");
    ASSERT_TRUE(state.fitBudget.running()) << panel.fit.message;
    for (int i = 0; i < 5; ++i) state.fitBudget.step(*session);
    EXPECT_EQ(allKnobs(*session), before);
    driver.click("pareto.fit_cancel");
    EXPECT_FALSE(state.fitBudget.running());
    EXPECT_FALSE(state.fitBudget.step(*session));
    for (int i = 0; i < 3; ++i) driver.frame();
    EXPECT_EQ(allKnobs(*session), before);
    EXPECT_FALSE(panel.fit.change);
    EXPECT_NE(panel.fit.message.find("cancelled"), std::string::npos) << panel.fit.message;

    // Another render size part-way stops it, said so; nothing applied.
    driver.click("pareto.fit_budget");
    ASSERT_TRUE(state.fitBudget.running()) << panel.fit.message;
    state.fitBudget.step(*session);
    session->resize(40, 20);
    EXPECT_FALSE(state.fitBudget.step(*session));
    driver.frame();
    EXPECT_NE(panel.fit.message.find("fit budget stopped: the view changed size during the sweep"), std::string::npos)
        << panel.fit.message;
    EXPECT_EQ(allKnobs(*session), before);
    session->resize(32, 18);
    session->render({{"final"}});

    // A budget nothing fits: says so with the cheapest point's time, applies nothing, measures nothing.
    panel.budgetMs = 0.0001;
    driver.click("pareto.fit_budget");
    ASSERT_TRUE(state.fitBudget.running()) << panel.fit.message;
    runFit(state, *session);
    ASSERT_TRUE(state.fitBudget.done()) << state.fitBudget.error();
    driver.frame();
    EXPECT_EQ(state.fitBudget.pick().point, -1);
    EXPECT_GE(state.fitBudget.pick().cheapest, 0);
    ASSERT_FALSE(panel.fit.pickLines.empty());
    EXPECT_NE(panel.fit.pickLines[0].find("none fits the budget of 0.0001 ms"), std::string::npos) << panel.fit.pickLines[0];
    EXPECT_NE(panel.fit.pickLines[0].find("the cheapest, point"), std::string::npos) << panel.fit.pickLines[0];
    EXPECT_NE(panel.fit.message.find("nothing applied"), std::string::npos) << panel.fit.message;
    EXPECT_TRUE(drawnNow("pareto.fit_pick") && drawnNow("pareto.fit_message"));
    EXPECT_FALSE(drawnNow("pareto.fit_undo"));
    EXPECT_EQ(allKnobs(*session), before);
    EXPECT_FALSE(state.measure.active());
    EXPECT_FALSE(panel.fit.change);
}
