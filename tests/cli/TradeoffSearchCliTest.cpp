// `tradeoff --search --budget-ms X` (BudgetSearch) and `tradeoff merge
// --budget-ms X` end to end on tiny images (48x27, six frames): every
// evaluation a row of the CSV with its step and proposal, the bound held,
// the result inside the budget; a merge's pick the same as the one a run's
// table gives; records that replay the pick and the search; bad input
// refused in one line before anything renders. Timings are never asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "renderer/bench/BudgetPick.h"
#include "renderer/bench/TradeoffTable.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

using Result = test::CommandResult;

fs::path dir() {
    static const fs::path d = [] {
        fs::path p = test::tempDir() / "tradeoff-search";
        fs::create_directories(p);
        return p;
    }();
    return d;
}

Result run(const std::string& args) {
    return test::runCommand("DW_REFERENCE_CACHE=" + (dir() / "cache").string() + " " + DW_WORKBENCH_BINARY + " " + args);
}

std::string files(const std::string& name) {
    return " --csv " + (dir() / (name + ".csv")).string() + " --record " + (dir() / (name + ".json")).string() +
           " --plot none";
}

const std::string kTiny = "tradeoff --scene default --size 48x27 --metric rms --frames 6 --warmup 1 --resamples 200 --quiet ";

nlohmann::json readJson(const fs::path& p) {
    std::ifstream f(p);
    return nlohmann::json::parse(f);
}

}  // namespace

// Every evaluation is a row (point = its number, with the step that proposed
// it); the evaluations stay under --max-evals; what it found fits the budget
// (its time's interval under it) and is the row the summary names.
TEST(TradeoffSearchCli, EveryEvaluationARowUnderTheBoundAndTheResultFits) {
    const Result r = run(kTiny + "--search --budget-ms 100000 --max-evals 10" + files("search"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "search.csv").string());
    ASSERT_GE(t.axes.size(), 3u);
    EXPECT_EQ(t.axes[0], "step");
    EXPECT_EQ(t.axes[1], "proposal");
    ASSERT_GE(t.rows.size(), 2u);
    EXPECT_LE(t.rows.size(), 10u);
    for (size_t i = 0; i < t.rows.size(); ++i) {
        EXPECT_EQ(t.rows[i].point, static_cast<int>(i));  // one camera: a row per evaluation
        EXPECT_FALSE(t.axisValue(t.rows[i], "step").empty());
        EXPECT_TRUE(std::isfinite(t.rows[i].error));
        EXPECT_FALSE(t.rows[i].pick.empty());  // the step's pick column
    }
    EXPECT_EQ(t.axisValue(t.rows[0], "proposal"), "start");
    EXPECT_EQ(t.axisValue(t.rows[0], "step"), "1");
    const std::string count = std::to_string(t.rows.size()) + " evaluation(s) in ";
    EXPECT_NE(r.out.find("search: " + count), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("(bound 10)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("the grid of --knobs speed/quality about the same start has "), std::string::npos) << r.out;
    std::smatch m;
    const std::regex found("search: evaluation ([0-9]+): rms [^\\n]* fits the budget of 1e\\+05 ms");
    ASSERT_TRUE(std::regex_search(r.out, m, found)) << r.out;
    const int evaluation = std::stoi(m[1]);
    ASSERT_LT(static_cast<size_t>(evaluation), t.rows.size());
    const TradeoffRow& best = t.rows[static_cast<size_t>(evaluation)];
    EXPECT_LT(best.timeMsHi, 100000.0);
    EXPECT_TRUE(best.pick == "pick" || best.pick == "tied" || best.pick == "fits") << best.pick;
    // The record keeps the search, its bound and the budget.
    const nlohmann::json rec = readJson(dir() / "search.json");
    EXPECT_EQ(rec["grid"]["search"]["max_evals"], 10);
    EXPECT_EQ(rec["grid"]["budget_ms"], 100000.0);
    EXPECT_EQ(rec["results"]["settings"]["search_found_evaluation"], std::to_string(evaluation));
}

// A budget nothing fits: the search walks toward it (cheaper), and says the result does not fit.
TEST(TradeoffSearchCli, ABudgetNothingFitsSaysSo) {
    const Result r = run(kTiny + "--search --budget-ms 0.0001 --max-evals 6" + files("search-none"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("does not fit the budget of 0.0001 ms"), std::string::npos) << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "search-none.csv").string());
    EXPECT_LE(t.rows.size(), 6u);
    for (const auto& row : t.rows) EXPECT_EQ(row.pick, "over");
}

// A search record replays: the same start, budget and bound; with every
// point fitting the move is decided by the error alone (deterministic), so
// replay finds the same settings.
TEST(TradeoffSearchCli, ASearchRecordReplaysTheSameSettings) {
    const Result r = run(kTiny + "--search --budget-ms 100000 --max-evals 4" + files("search-replay"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const Result again = run("replay " + (dir() / "search-replay.json").string());
    EXPECT_EQ(again.code, 0) << again.err << again.out;
    EXPECT_NE(again.out.find("search: the same settings found"), std::string::npos) << again.out;
}

// Replay of a search checks every evaluation both walks measured with the
// same settings, not only the settings found: a record edited in one
// evaluation's error and another's counter makes replay name those numbers,
// say "tradeoff: differs" and exit 1; the unedited record says "the same".
TEST(TradeoffSearchCli, ASearchReplayChecksEveryEvaluationsNumbers) {
    const Result r = run(kTiny + "--search --cost fragments --budget 4e6 --max-evals 8" + files("search-checked"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    // Unedited: every evaluation met again, its error and counters equal.
    const Result same = run("replay " + (dir() / "search-checked.json").string());
    EXPECT_NE(same.out.find("search: the same settings found"), std::string::npos) << same.out;
    const TradeoffTable walked = TradeoffTable::readCsv((dir() / "search-checked.csv").string());
    const std::string all = "search: " + std::to_string(walked.rows.size()) +
                            " evaluation(s) with the same settings in both walks compared; 0 only in the record, 0 only "
                            "in this walk";
    EXPECT_NE(same.out.find(all), std::string::npos) << same.out;
    EXPECT_EQ(same.out.find("(differs)"), std::string::npos) << same.out;
    EXPECT_EQ(same.out.find("counters moved"), std::string::npos) << same.out;
    EXPECT_EQ(same.out.find("counters not measured here"), std::string::npos) << same.out;
    // The front's cost is a counter: the times are printed, not counted, so the verdict is "the same".
    EXPECT_EQ(same.code, 0) << same.out;
    EXPECT_NE(same.out.find("every counter equal"), std::string::npos) << same.out;
    EXPECT_NE(same.out.find("times not counted: the front's cost is a counter"), std::string::npos) << same.out;

    nlohmann::json rec = readJson(dir() / "search-checked.json");
    nlohmann::json& rows = rec["results"]["rows"];
    ASSERT_GE(rows.size(), 2u);
    const double error = rows[0]["error"].get<double>();
    rows[0]["error"] = error * 2.0;
    nlohmann::json& fragments = rows[1]["counters"]["frame"]["fragments"];
    const double counted = fragments.get<double>();
    fragments = 123.0;
    std::ofstream((dir() / "search-edited.json").string()) << rec.dump(2);
    const Result moved = run("replay " + (dir() / "search-edited.json").string());
    EXPECT_EQ(moved.code, 1) << moved.err << moved.out;
    EXPECT_NE(moved.out.find(", step=1, proposal=start"), std::string::npos) << moved.out;
    // The found point's counter, the budget's own cost, is on the search line.
    const size_t line = moved.out.find("search: the same settings found");
    ASSERT_NE(line, std::string::npos) << moved.out;
    EXPECT_LT(moved.out.find(", fragments ", line), moved.out.find('\n', line)) << moved.out;
    EXPECT_NE(moved.out.find("(differs)"), std::string::npos) << moved.out;
    char counter[96];
    std::snprintf(counter, sizeof counter, "counters moved: fragments 123 -> %.17g", counted);
    EXPECT_NE(moved.out.find(counter), std::string::npos) << moved.out;
    EXPECT_NE(moved.out.find("tradeoff: differs (1 row(s) with another error"), std::string::npos) << moved.out;
    EXPECT_NE(moved.out.find("1 with a counter moved"), std::string::npos) << moved.out;
}

// tradeoff merge --budget-ms: the pick over the merged rows is the point the
// unmerged table's pick is (same rows), with the merge's intervals rule said;
// a budgeted record keeps --time and the budget, and replay says the pick is the same.
TEST(TradeoffSearchCli, MergePicksAsTheRunAndRecordsReplayThePick) {
    const std::string sweep = kTiny + "--sweep ssao.samples=4,32 --sweep ssao.resolution=full,quarter --time ao ";
    const Result r = run(sweep + "--budget-ms 100000" + files("budgeted"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    TradeoffTable t = TradeoffTable::readCsv((dir() / "budgeted.csv").string());
    ASSERT_EQ(t.rows.size(), 4u);
    // A budget between the cheapest and the dearest upper bound, so it chooses.
    std::vector<double> his;
    for (const auto& row : t.rows) his.push_back(row.timeMsHi);
    std::sort(his.begin(), his.end());
    const double budget = (his[1] + his[2]) / 2.0;
    const BudgetPick expected = BudgetPicker::pick(t, budget, BudgetPicker::shownCamera(t));
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", budget);
    const std::string out = (dir() / "merged.csv").string();
    const Result merged = run("tradeoff merge " + (dir() / "budgeted.csv").string() + " --out " + out +
                              " --plot none --time ao --record " + (dir() / "merged.json").string() + " --budget-ms " + text);
    ASSERT_EQ(merged.code, 0) << merged.err << merged.out;
    EXPECT_NE(merged.out.find("pick: over the merged shards the error ties are the intervals rule's"), std::string::npos)
        << merged.out;
    const TradeoffTable m = TradeoffTable::readCsv(out);
    int picked = -1;
    for (const auto& row : m.rows)
        if (row.pick == "pick") picked = row.point;
    EXPECT_EQ(picked, expected.point);
    if (expected.point >= 0) {
        EXPECT_NE(merged.out.find("pick: point " + std::to_string(expected.point)), std::string::npos) << merged.out;
    }

    // The merged record keeps the budget and the pick's lines, as a run's does.
    const nlohmann::json mergedRecord = readJson(dir() / "merged.json");
    EXPECT_TRUE(mergedRecord["results"]["settings"]["budget_ms"].is_string());
    EXPECT_TRUE(mergedRecord["results"]["settings"]["pick"].is_array());
    const nlohmann::json rec = readJson(dir() / "budgeted.json");
    EXPECT_EQ(rec["grid"]["time"], "ao");
    EXPECT_EQ(rec["grid"]["budget_ms"], 100000.0);
    EXPECT_TRUE(rec["grid"]["search"].is_null());
    const Result again = run("replay " + (dir() / "budgeted.json").string());
    EXPECT_NE(again.out.find("pick: the same: point "), std::string::npos) << again.out << again.err;
}

// Bad input: one line naming what was wrong, exit 2, nothing written.
TEST(TradeoffSearchCli, BadInputIsOneClearLine) {
    struct Bad {
        std::string args, says;
    };
    for (const Bad& b : {Bad{"--search", "--search needs a budget: --budget-ms X"},
                         Bad{"--search --budget-ms 5 --max-evals 0", "--max-evals"},
                         Bad{"--search --budget-ms 5 --sweep ssao.samples=4,8", "--search walks the speed/quality knobs itself"},
                         Bad{"--search --budget-ms 5 --shard 0/2", "--search cannot be sharded"},
                         Bad{"--budget-ms 5 --knobs speed/quality --max-evals 4", "--max-evals bounds --search"},
                         Bad{"--search --budget-ms 0", "--budget-ms"}}) {
        const Result r = run(kTiny + b.args + files("search-bad"));
        EXPECT_EQ(r.code, 2) << b.args << "\n" << r.err;
        // One line saying what was wrong (then the usage hint).
        EXPECT_NE(r.err.substr(0, r.err.find('\n')).find(b.says), std::string::npos) << b.args << "\n" << r.err;
        EXPECT_NE(r.err.find("(deferred-workbench help tradeoff lists its options)"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir() / "search-bad.csv")) << b.args;
    }
    for (const Bad& b : {Bad{"--budget-ms 5 --budget 7", "--budget-ms and --budget: give one"},
                         Bad{"--budget 7", "--budget bounds a counter"},
                         Bad{"--budget-ms nan", "--budget-ms"}}) {
        const Result r = run("tradeoff merge " + (dir() / "none.csv").string() + " --out " +
                             (dir() / "merge-bad.csv").string() + " --plot none " + b.args);
        EXPECT_EQ(r.code, 2) << b.args << "\n" << r.err;
        EXPECT_NE(r.err.find(b.says), std::string::npos) << b.args << "\n" << r.err;
    }
}
