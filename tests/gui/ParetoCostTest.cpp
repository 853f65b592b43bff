// Issue 34 in the window: the Pareto panel's cost axis. A CSV written for
// `tradeoff --cost fragments` (its pareto column decided on fragments) opens
// with fragments across (exact: the points where their counts put them) and
// the budget field in fragments; the pick is the one `tradeoff merge X.csv
// --cost fragments --budget N` prints on the same CSV; gpu_ms across puts
// the points at their times and says the marks are the CSV's for fragments;
// a budget above the CLI's range is refused on screen in the CLI's words.
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include "renderer/bench/TradeoffTable.h"
#include "tests/gui/HeadlessImGui.h"
#include "tests/support/TestSupport.h"
#include "ui/ParetoPanel.h"
#include "ui/Widgets.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

bool drawnNow(const std::string& name) {
    const auto& items = ui::drawnItems();
    return items.count(name) && items.at(name).frame == ImGui::GetFrameCount();
}

// The first line of `text` that starts with `prefix` ("" when none).
std::string lineStarting(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0) return line;
    return "";
}

// Four points of ssao.samples: by time point 1 (30 ms) is off the front
// (point 2 is faster and better); by fragments every point is on it. The
// front is decided on fragments, as tradeoff --cost fragments writes it.
fs::path fragmentsCsv() {
    TradeoffTable t;
    t.axes = {"ssao.samples"};
    t.counted = true;
    const double errors[] = {0.040, 0.030, 0.020, 0.010}, times[] = {10.0, 30.0, 20.0, 40.0},
                 fragments[] = {1000, 2000, 5000, 9000};
    for (int i = 0; i < 4; ++i) {
        TradeoffRow r;
        r.point = i;
        r.axisValues = {std::to_string(4 << i)};
        r.camera = "0";
        r.metric = "rms";
        r.buffer = "ao";
        r.error = errors[i], r.errorLo = r.error * 0.95, r.errorHi = r.error * 1.05;
        r.frames = 8;
        r.frameGpuMs = times[i], r.frameGpuMsLo = times[i] * 0.95, r.frameGpuMsHi = times[i] * 1.05;
        for (size_t c = 0; c < PassCounts::kCount; ++c) r.frameCounts[c] = 100.0 * static_cast<double>(c + 1);
        r.frameCounts[PassCounts::Fragments] = fragments[i];
        t.rows.push_back(r);
    }
    t.markParetoFront("frame", "fragments");
    const fs::path csv = test::tempDir() / "pareto-cost-fragments.csv";
    t.writeCsv(csv.string());
    return csv;
}

}  // namespace

TEST(ParetoCost, ACounterAcrossPicksAsTheCliDoesAndTheBudgetIsRefusedAsTheCliRefusesIt) {
    const fs::path csv = fragmentsCsv();
    auto session = test::makeSession(32, 18);
    session->loadScene("spheres");
    test::HeadlessImGui imgui(ImVec2(800, 700));
    ui::UiState state;
    ui::ParetoPanel panel;
    ASSERT_TRUE(panel.load(csv.string())) << panel.error;
    bool open = true;
    auto draw = [&] {
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(800, 700));
        panel.draw("Pareto", &open, state, *session);
    };
    const auto x = [](int point) { return ui::drawnItems().at("pareto.point." + std::to_string(point)).x; };

    // The CSV's own cost, found from its pareto column, is the default; the combo offers every counter it holds.
    EXPECT_EQ(panel.csvCost, "fragments");
    EXPECT_EQ(panel.cost, "fragments");
    const std::vector<std::string> costs = panel.costs();
    EXPECT_EQ(costs.size(), 1u + PassCounts::kCount);
    EXPECT_EQ(costs.front(), "gpu_ms");
    imgui.frame(draw);
    EXPECT_TRUE(drawnNow("pareto.cost"));
    EXPECT_FALSE(drawnNow("pareto.marks_cost"));
    // Across by fragments: point 1 (2000) left of point 2 (5000), at their counts' ratio.
    EXPECT_LT(x(1), x(2));
    EXPECT_NEAR((x(2) - x(0)) / (x(3) - x(0)), 4000.0 / 8000.0, 0.01);

    // A budget of 5500 fragments: points 0, 1 and 2 fit (exact), the least error is point 2: as the CLI picks.
    panel.budgetCount = 5500;
    imgui.frame(draw);
    ASSERT_FALSE(panel.pickLines.empty());
    EXPECT_EQ(panel.table.rows[2].pick, "pick");
    EXPECT_EQ(panel.table.rows[3].pick, "over");
    EXPECT_TRUE(drawnNow("pareto.pick"));
    const fs::path merged = test::tempDir() / "pareto-cost-merged.csv";
    const test::CommandResult cli =
        test::runWorkbench("tradeoff merge " + csv.string() + " --out " + merged.string() + " --cost fragments --budget 5500");
    ASSERT_EQ(cli.code, 0) << cli.err;
    const std::string cliPick = lineStarting(cli.out, "pick: ");
    ASSERT_FALSE(cliPick.empty()) << cli.out;
    EXPECT_EQ(cliPick.rfind("pick: point 2 (ssao.samples=16)", 0), 0u) << cliPick;
    EXPECT_EQ(panel.pickLines[0], cliPick);
    // The ties and the front's rule (not in the CSV) as the CLI decides them: its second line, word for word.
    ASSERT_GE(panel.pickLines.size(), 2u);
    const std::string cliTies = lineStarting(cli.out.substr(cli.out.find(cliPick) + cliPick.size()), "pick: ");
    EXPECT_EQ(panel.pickLines[1], cliTies);

    // gpu_ms across: the points at their times (point 1 at 30 ms right of point 2 at 20 ms), the
    // marks said to be the CSV's for fragments, the budget field back in ms.
    panel.cost = "gpu_ms";
    imgui.frame(draw);
    EXPECT_GT(x(1), x(2));
    EXPECT_TRUE(drawnNow("pareto.marks_cost"));
    EXPECT_TRUE(panel.table.rows[1].pareto);  // the CSV's mark, kept

    // Above the CLI's range: refused on screen with the CLI's message (only the value's spelling is the CLI's own).
    panel.budgetMs = 2e9;
    imgui.frame(draw);
    ASSERT_EQ(panel.pickLines.size(), 1u);
    EXPECT_EQ(panel.pickLines[0], "--budget-ms must be a number above 0 and at most 1000000000 (GPU milliseconds), got '2000000000'");
    EXPECT_TRUE(drawnNow("pareto.pick"));
    const test::CommandResult cliMs =
        test::runWorkbench("tradeoff merge " + csv.string() + " --out " + merged.string() + " --budget-ms 2000000000");
    EXPECT_NE(cliMs.code, 0);
    EXPECT_NE(cliMs.err.find(panel.pickLines[0]), std::string::npos) << cliMs.err;
    panel.cost = "fragments";
    panel.budgetCount = 2e18;
    imgui.frame(draw);
    ASSERT_EQ(panel.pickLines.size(), 1u);
    EXPECT_EQ(panel.pickLines[0], "--budget must be a number above 0 and at most 1e+18 (the --cost counter's unit), got '2e+18'");
    const test::CommandResult cliCount =
        test::runWorkbench("tradeoff merge " + csv.string() + " --out " + merged.string() + " --cost fragments --budget 2e+18");
    EXPECT_NE(cliCount.code, 0);
    EXPECT_NE(cliCount.err.find(panel.pickLines[0]), std::string::npos) << cliCount.err;
    for (const auto& r : panel.table.rows) EXPECT_TRUE(r.pick.empty()) << r.point;
}
