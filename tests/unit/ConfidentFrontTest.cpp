// The front decided with its noise (issue 34): the paired test on synthetic
// draws (a clear win, a tie of noise, identical errors), Holm's adjustment,
// dominance that point estimates alone would get wrong, the CSV's new
// columns, --time sums, and the budget's pick.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "renderer/Error.h"
#include "renderer/bench/BudgetPick.h"
#include "renderer/bench/ConfidentFront.h"
#include "renderer/bench/TradeoffEvidence.h"
#include "renderer/bench/TradeoffTable.h"

using namespace dw;

namespace {

constexpr int kDraws = 2000;

// A reproducible value in [-0.5, 0.5) (no <random> distribution: they differ between libraries).
double noise(unsigned& state) {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24) - 0.5;
}

// Draws about `centre`: `shared` of each draw's noise is common to every point (the pairing), `own` is its own.
std::vector<double> draws(double centre, double shared, double own, unsigned seed) {
    unsigned common = 7u, mine = seed;
    std::vector<double> d;
    for (int b = 0; b < kDraws; ++b) d.push_back(centre + shared * noise(common) + own * noise(mine));
    return d;
}

FrontAxis axis(double value, std::vector<double> d) {
    FrontAxis a;
    a.value = value;
    a.lo = a.hi = std::numeric_limits<double>::quiet_NaN();
    a.draws = std::move(d);
    return a;
}

FrontEvidence point(double time, double timeNoise, double error, double errorNoise, unsigned seed) {
    return {axis(time, draws(time, 1.0, timeNoise, seed)), axis(error, draws(error, 0.01, errorNoise, seed + 100))};
}

}  // namespace

TEST(ConfidentFront, PairedTestSeesAClearWin) {
    // b is 0.2 above a in every draw, under shared noise five times as large: paired, it is certain.
    const PairedTest t = pairedTest(draws(1.0, 1.0, 0.0, 1), draws(1.2, 1.0, 0.0, 2));
    EXPECT_FALSE(t.identical);
    EXPECT_EQ(t.favours, -1);
    EXPECT_LT(t.p, 0.001);
}

TEST(ConfidentFront, PairedTestCallsNoiseATie) {
    // The same centre, each side's own noise: no side wins.
    const PairedTest t = pairedTest(draws(1.0, 0.0, 0.1, 3), draws(1.001, 0.0, 0.1, 4));
    EXPECT_FALSE(t.identical);
    EXPECT_GT(t.p, 0.5);
}

TEST(ConfidentFront, IdenticalErrorsAreIdenticalAndNotWorse) {
    const std::vector<double> same = draws(0.06, 0.01, 0.0, 5);
    const PairedTest t = pairedTest(same, same);
    EXPECT_TRUE(t.identical);
    EXPECT_EQ(t.p, 1.0);
    // Point 1: the same error bit for bit, clearly slower: dominated by 0 (an identical error is not worse).
    std::vector<FrontEvidence> pts = {point(1.0, 0.001, 0.06, 0.0, 10), point(2.0, 0.001, 0.06, 0.0, 20)};
    pts[1].error = pts[0].error;
    const FrontDecision d = decideFront(pts, FrontRule::pairedBootstrap);
    EXPECT_EQ(d.front[0], "pareto");
    EXPECT_EQ(d.front[1], "dominated");
    EXPECT_EQ(d.dominatedBy[1], std::vector<size_t>{0});
    EXPECT_EQ(d.errorOrder[0][1], Order::identical);
    EXPECT_TRUE(d.errorTied(0, 1));
}

TEST(ConfidentFront, HolmStepsDown) {
    // m = 3: 0.01 <= 0.05/3, 0.02 <= 0.05/2, 0.04 <= 0.05/1: all three; with 0.03 first at 0.05/3 none.
    EXPECT_EQ(holmRejects({0.04, 0.01, 0.02}, 0.05), (std::vector<bool>{true, true, true}));
    EXPECT_EQ(holmRejects({0.03, 0.03, 0.03}, 0.05), (std::vector<bool>{false, false, false}));
    EXPECT_EQ(holmRejects({0.001, 0.5}, 0.05), (std::vector<bool>{true, false}));
}

// The case point estimates get wrong: point 1 is slower and has more error than
// point 0 by its estimates, so off the front, but its error is within noise of
// point 0's. A point-estimate rule calls it dominated; it is indistinguishable.
TEST(ConfidentFront, DominanceNeedsConfidenceNotPointEstimates) {
    const std::vector<FrontEvidence> pts = {point(1.0, 0.001, 0.0610, 0.02, 30), point(2.0, 0.001, 0.0615, 0.02, 40),
                                            point(3.0, 0.001, 0.2, 0.0, 50)};
    const FrontDecision d = decideFront(pts, FrontRule::pairedBootstrap);
    EXPECT_EQ(d.front[0], "pareto");
    EXPECT_EQ(d.front[1], "indistinguishable");  // ParetoFront alone: off the front, i.e. "dominated"
    EXPECT_TRUE(d.dominatedBy[1].empty());
    EXPECT_EQ(d.front[2], "dominated");  // slower and clearly worse: confidently dominated
    EXPECT_EQ(d.dominatedBy[2], std::vector<size_t>{0});
    // 0 and 1 cannot be told apart in error; in time they can.
    ASSERT_EQ(d.tiedWith[0].size(), 1u);
    EXPECT_EQ(d.tiedWith[0][0].other, 1u);
    EXPECT_TRUE(d.tiedWith[0][0].error);
    EXPECT_FALSE(d.tiedWith[0][0].time);
    EXPECT_EQ(d.comparisons, 6);  // 3 pairs x 2 axes
    EXPECT_NE(d.rule.find("Holm"), std::string::npos);
    // Without draws the same estimates decide nothing by the draws rule.
    std::vector<FrontEvidence> bare = pts;
    for (auto& p : bare) p.cost.draws.clear(), p.error.draws.clear();
    EXPECT_EQ(decideFront(bare, FrontRule::pairedBootstrap).front[2], "indistinguishable");
}

TEST(ConfidentFront, IntervalsRuleNeedsIntervalsApart) {
    std::vector<FrontEvidence> pts(3);
    pts[0] = {{1.0, 0.9, 1.1, {}, false}, {0.05, 0.04, 0.06, {}, false}};
    pts[1] = {{2.0, 1.9, 2.1, {}, false}, {0.055, 0.045, 0.065, {}, false}};  // error overlaps 0's
    pts[2] = {{3.0, 2.9, 3.1, {}, false}, {0.2, 0.19, 0.21, {}, false}};      // apart on both
    const FrontDecision d = decideFront(pts, FrontRule::intervals);
    EXPECT_EQ(d.front[1], "indistinguishable");
    EXPECT_EQ(d.front[2], "dominated");
    EXPECT_NE(d.rule.find("do not overlap"), std::string::npos);
}

TEST(ConfidentFront, ExactCostsNeedNoTest) {
    // A counter as the cost (ConfidentFront is generic over the cost): exact, so told apart by value.
    std::vector<FrontEvidence> pts = {point(1.0, 0.0, 0.05, 0.0, 60), point(2.0, 0.0, 0.2, 0.0, 70)};
    for (auto& p : pts) p.cost.draws.clear(), p.cost.exact = true;
    const FrontDecision d = decideFront(pts, FrontRule::pairedBootstrap);
    EXPECT_EQ(d.timeOrder[0][1], Order::firstBetter);
    EXPECT_EQ(d.front[1], "dominated");
    EXPECT_EQ(d.comparisons, 1);  // the error's test only
}

TEST(TradeoffEvidence, TimeDrawsPairRoundsAndSumTermsWithinAFrame) {
    // Two passes in two frames of one configuration: the sum is per frame.
    std::vector<BenchSample> s;
    auto add = [&](int sample, const char* series, double ms) {
        BenchSample b;
        b.config = 0;
        b.sample = sample;
        b.series = series;
        b.gpuMs = ms;
        s.push_back(b);
    };
    add(0, "lighting", 10.0), add(0, "ao", 1.0), add(0, "frame", 20.0);
    add(1, "lighting", 30.0), add(1, "ao", 3.0), add(1, "frame", 40.0);
    const FrameTimes sum = frameTimes(s, TradeoffTable::timeTerms("lighting+ao"));
    EXPECT_EQ(sum.at(0).at(0), 11.0);
    EXPECT_EQ(sum.at(0).at(1), 33.0);
    EXPECT_EQ(frameTimes(s, {"frame"}).at(0).at(1), 40.0);
    EXPECT_THROW(TradeoffTable::timeTerms("lighting++ao"), Error);
    EXPECT_THROW(TradeoffTable::timeTerms("ao+ao"), Error);
    EXPECT_THROW(TradeoffTable::timeTerms("frame+ao"), Error);
    // Two frames are too few rounds to resample: no draws, so time is never told apart.
    RowData a;
    a.frames = {&sum.at(0)};
    const EvidenceDraws how{500, 1, 9};
    EXPECT_TRUE(rowEvidence(a, how).cost.draws.empty());
    // Six rounds: two rows with the same frames draw the same medians (the same rounds).
    std::map<int, double> six;
    for (int k = 0; k < 6; ++k) six[k] = 10.0 + k;
    a.frames = {&six};
    EXPECT_EQ(rowEvidence(a, how).cost.draws, rowEvidence(a, how).cost.draws);
    EXPECT_EQ(rowEvidence(a, how).cost.draws.size(), 500u);
    // With --block 2 the six frames are three rounds: too few again.
    EXPECT_TRUE(rowEvidence(a, EvidenceDraws{500, 2, 9}).cost.draws.empty());
}

namespace {

TradeoffTable budgetTable() {
    TradeoffTable t;
    t.axes = {"ssao.samples"};
    t.time = "ao";
    const double err[] = {0.20, 0.10, 0.0995, 0.05};
    const double ms[] = {1.0, 2.0, 2.5, 9.0};
    for (int i = 0; i < 4; ++i) {
        TradeoffRow r;
        r.point = i;
        r.axisValues = {std::to_string(4 << i)};
        r.camera = "0";
        r.metric = "rms";
        r.buffer = "ao";
        r.error = err[i], r.errorLo = err[i] - 0.01, r.errorHi = err[i] + 0.01;
        r.frames = 5;
        r.frameGpuMs = r.frameGpuMsLo = r.frameGpuMsHi = 100.0;
        r.timeMs = ms[i], r.timeMsLo = ms[i] - 0.2, r.timeMsHi = ms[i] + 0.2;
        t.rows.push_back(r);
    }
    t.markFront([&](size_t i) { return t.intervalEvidence(t.rows[i]); }, FrontRule::intervals);
    return t;
}

}  // namespace

TEST(BudgetPick, PicksTheLeastErrorUnderTheBudgetAndNamesItsTies) {
    TradeoffTable t = budgetTable();
    const BudgetPick p = BudgetPicker::pick(t, 3.0, "0");
    EXPECT_EQ(p.point, 2);  // 0.0995, its time's interval ends at 2.7 < 3
    EXPECT_EQ(p.fitting, 3);
    EXPECT_EQ(p.tied, std::vector<int>{1});  // 0.10: its interval overlaps
    EXPECT_EQ(t.rows[2].pick, "pick");
    EXPECT_EQ(t.rows[1].pick, "tied");
    EXPECT_EQ(t.rows[0].pick, "fits");
    EXPECT_EQ(t.rows[3].pick, "over");
    ASSERT_FALSE(p.lines.empty());
    EXPECT_EQ(p.lines[0].rfind("pick: point 2 (ssao.samples=16)", 0), 0u) << p.lines[0];
    EXPECT_NE(p.lines[1].find("cannot be told apart in error from point(s) 1"), std::string::npos) << p.lines[1];
    // The interval's upper end counts, not the median: 2.4 + 0.2 is not under 2.5.
    EXPECT_EQ(BudgetPicker::pick(t, 2.5, "0").point, 1);
}

TEST(BudgetPick, NoneFitsSaysTheCheapestWithItsInterval) {
    TradeoffTable t = budgetTable();
    const BudgetPick p = BudgetPicker::pick(t, 1.1, "0");
    EXPECT_EQ(p.point, -1);
    EXPECT_EQ(p.cheapest, 0);
    ASSERT_EQ(p.lines.size(), 1u);
    EXPECT_NE(p.lines[0].find("none fits the budget of 1.1 ms"), std::string::npos) << p.lines[0];
    EXPECT_NE(p.lines[0].find("ao time 1 ms [0.8, 1.2]"), std::string::npos) << p.lines[0];
}

TEST(BudgetPick, AnyCostOfARowCanBeTheBudgetsUnit) {
    // A counter as the cost (issue 34's --cost): exact, held against the budget as it is.
    TradeoffTable t = budgetTable();
    const BudgetCost fragments{"fragments", "fragments", true, [](const TradeoffRow& r, double& v, double& lo, double& hi) {
                                   v = lo = hi = 1000.0 * (r.point + 1);
                               }};
    const BudgetPick p = BudgetPicker::pick(t, 2500.0, "0", fragments);
    EXPECT_EQ(p.point, 1);  // 1000 and 2000 fit; 2000's error is the lower
    EXPECT_NE(p.lines[0].find("fragments 2000 fragments: the least error"), std::string::npos) << p.lines[0];
    EXPECT_NE(p.lines[0].find("(exact)"), std::string::npos) << p.lines[0];
    EXPECT_THROW(BudgetPicker::pick(t, 0.0, "0", fragments), Error);
}

// A trial found the pick claiming 97.5% from one frame, and "told apart from
// every other point that fits" when no other fits.
TEST(BudgetPick, ClaimsNoConfidenceFromTooFewFramesAndSaysWhenOnlyOneFits) {
    TradeoffTable t = budgetTable();
    for (auto& r : t.rows) r.frames = 1;
    const BudgetPick p = BudgetPicker::pick(t, 1.3, "0");  // only point 0 (1 ms [0.8, 1.2]) fits
    ASSERT_EQ(p.point, 0);
    ASSERT_EQ(p.lines.size(), 2u);
    EXPECT_NE(p.lines[0].find("1 counted frame(s): too few frames for an interval, so no confidence"), std::string::npos)
        << p.lines[0];
    EXPECT_EQ(p.lines[0].find("97.5%"), std::string::npos) << p.lines[0];
    EXPECT_EQ(p.lines[1], "pick: the only point that fits");
}

TEST(BudgetPick, RefusesBudgetsThatAreNotMilliseconds) {
    // What the command line refuses (OptionLimits' kBudgetMs: above 0, at most 1e9), in its words.
    for (double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity(), 1e9 * 1.5}) {
        try {
            BudgetPicker::check(bad);
            ADD_FAILURE() << bad;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()).rfind("--budget-ms must be a number above 0 and at most 1000000000 "
                                                  "(GPU milliseconds), got '",
                                                  0),
                      0u)
                << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        }
    }
    EXPECT_NO_THROW(BudgetPicker::check(1e9));
    // A counter's budget: kBudget (at most 1e18), named --budget.
    EXPECT_NO_THROW(BudgetPicker::check(1e18, "--budget"));
    try {
        BudgetPicker::check(2e18, "--budget");
        ADD_FAILURE() << "2e18 taken";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "--budget must be a number above 0 and at most 1e+18 (the --cost counter's unit), got '2e+18'");
    }
}

TEST(TradeoffTableFront, NewColumnsReadBackAndOldCsvStillReads) {
    TradeoffTable t = budgetTable();
    BudgetPicker::pick(t, 3.0, "0");
    const TradeoffTable back = TradeoffTable::parseCsv(t.csv(), "t.csv");
    EXPECT_EQ(back.time, "ao");
    ASSERT_EQ(back.rows.size(), t.rows.size());
    for (size_t i = 0; i < t.rows.size(); ++i) {
        EXPECT_EQ(back.rows[i].front, t.rows[i].front);
        EXPECT_EQ(back.rows[i].dominatedBy, t.rows[i].dominatedBy);
        EXPECT_EQ(back.rows[i].tiedWith, t.rows[i].tiedWith);
        EXPECT_EQ(back.rows[i].pick, t.rows[i].pick);
        EXPECT_EQ(back.rows[i].timeMsHi, t.rows[i].timeMsHi);
    }
    EXPECT_EQ(t.rows[3].front, "pareto");
    EXPECT_EQ(t.rows[0].front, "pareto");
    // A CSV that ends at pareto (written before these columns) reads, ranked by frame time.
    const std::string old = "point,ssao.samples,camera,metric,buffer,error,error_lo,error_hi,frames,frame_gpu_ms,"
                            "frame_gpu_ms_lo,frame_gpu_ms_hi,gpu_ms.ao,pareto\n"
                            "0,4,0,rms,ao,0.1,0.09,0.11,5,10,9,11,1,1\n";
    const TradeoffTable o = TradeoffTable::parseCsv(old, "old.csv");
    EXPECT_EQ(o.rows[0].timeMs, 10.0);
    EXPECT_TRUE(o.rows[0].pareto);
    // A merge cannot make a sum's interval from medians: refused in one line.
    TradeoffTable m = o;
    EXPECT_THROW(m.rankBy("lighting+ao"), Error);
}

TEST(ConfidentFront, TooFewDrawsForHolmAreSaidAndTheNeededCountIsEnough) {
    // 9 points far apart on both axes (time 1..9, error 9..1 would be a front;
    // here time and error rise together, so point 0 dominates all in truth).
    // 72 comparisons at 2000 draws: the floor 2/2001 is above 0.05/72, so
    // nothing can be decided and the rule line says so.
    std::vector<FrontEvidence> pts;
    for (unsigned k = 0; k < 9; ++k) pts.push_back(point(1.0 + k, 0.01, 0.1 + 0.1 * k, 0.001, k + 1));
    const FrontDecision d = decideFront(pts, FrontRule::pairedBootstrap);
    EXPECT_EQ(d.comparisons, 72);
    EXPECT_EQ(d.draws, kDraws);
    EXPECT_EQ(frontDrawsNeeded(72, 0.05), 5760);
    EXPECT_NE(d.rule.find("no pair can be told apart: use --resamples 5760 or more"), std::string::npos) << d.rule;
    for (size_t p = 1; p < pts.size(); ++p) EXPECT_EQ(d.front[p], "indistinguishable");
    // Every draw favours point 0 (no own noise crosses a step of 1 ms or 0.1):
    // with the needed draws the same points are confidently dominated.
    std::vector<FrontEvidence> more;
    for (unsigned k = 0; k < 9; ++k) {
        FrontEvidence e = pts[k];
        for (FrontAxis* a : {&e.cost, &e.error}) {
            const std::vector<double> once = a->draws;
            while (a->draws.size() < 5760) a->draws.insert(a->draws.end(), once.begin(), once.end());
            a->draws.resize(5760);
        }
        more.push_back(e);
    }
    const FrontDecision enough = decideFront(more, FrontRule::pairedBootstrap);
    EXPECT_EQ(enough.rule.find("no pair can be told apart"), std::string::npos) << enough.rule;
    EXPECT_NE(enough.rule.find("from 5760 paired resamples"), std::string::npos) << enough.rule;
    for (size_t p = 1; p < more.size(); ++p) EXPECT_EQ(enough.front[p], "dominated") << p;
}

// A trial read "front: time: every pair of points told apart" under --cost
// fragments (the axis was the counter, never tested), Holm's "on each axis"
// when only the error was tested, and "cannot be told apart" in time from
// too few rounds: the lines name the cost axis and what was tested.
TEST(ConfidentFront, SummaryNamesTheCostAxisAndWhatWasTested) {
    // A counter as the cost: exact, compared by value; only the error tested.
    std::vector<FrontEvidence> pts = {point(1.0, 0.0, 0.05, 0.0, 60), point(2.0, 0.0, 0.2, 0.0, 70),
                                      point(3.0, 0.0, 0.01, 0.0, 80)};
    for (auto& p : pts) p.cost.draws.clear(), p.cost.exact = true;
    const FrontDecision exact = decideFront(pts, FrontRule::pairedBootstrap);
    EXPECT_EQ(exact.testedTime, 0);
    EXPECT_EQ(exact.testedError, 3);
    EXPECT_EQ(exact.exactCost, 3);
    EXPECT_NE(exact.rule.find("Holm's step-down over 3 comparison(s) (3 pair(s) on error only; the cost, an exact "
                              "counter, compared by value)"),
              std::string::npos)
        << exact.rule;
    // Time without draws (fewer than 6 rounds): not tested, and the rule says so.
    for (auto& p : pts) p.cost.exact = false;
    const FrontDecision untested = decideFront(pts, FrontRule::pairedBootstrap);
    EXPECT_EQ(untested.untestedTime, 3);
    EXPECT_NE(untested.rule.find("(3 pair(s) on error only; time not tested)"), std::string::npos) << untested.rule;
    // Both axes tested: as before.
    const FrontDecision both = decideFront({point(1.0, 0.001, 0.05, 0.0, 60), point(2.0, 0.001, 0.2, 0.0, 70)},
                                           FrontRule::pairedBootstrap);
    EXPECT_NE(both.rule.find("(every pair of points, on each axis)"), std::string::npos) << both.rule;

    // The table's summary lines, from the same kinds of evidence.
    TradeoffTable t = budgetTable();
    t.markFront(
        [&](size_t i) {
            FrontEvidence e = t.intervalEvidence(t.rows[i]);
            e.cost = {1000.0 * static_cast<double>(i), 1000.0 * static_cast<double>(i), 1000.0 * static_cast<double>(i),
                      {}, true};
            e.error.draws = draws(t.rows[i].error, 0.001, 0.0001, 90 + static_cast<unsigned>(i));
            return e;
        },
        FrontRule::pairedBootstrap);
    const std::vector<std::string> counted = t.frontSummary("0", "fragments");
    ASSERT_GE(counted.size(), 2u);
    EXPECT_EQ(counted[1], "fragments (an exact counter, compared by value, not tested): every pair of points differs");
    t.markFront(
        [&](size_t i) {
            FrontEvidence e = t.intervalEvidence(t.rows[i]);
            e.error.draws = draws(t.rows[i].error, 0.001, 0.0001, 90 + static_cast<unsigned>(i));
            return e;  // time: an interval, no draws
        },
        FrontRule::pairedBootstrap);
    const std::vector<std::string> fewRounds = t.frontSummary("0");
    ASSERT_GE(fewRounds.size(), 2u);
    EXPECT_EQ(fewRounds[1].rfind("time: not tested (no paired resamples: fewer than 6 rounds", 0), 0u) << fewRounds[1];
}

// "none fits" said the cheapest point's time with an interval from 2 frames, no caveat.
TEST(BudgetPick, NoneFitsSaysTooFewFramesForTheCheapestsInterval) {
    TradeoffTable t = budgetTable();
    for (auto& r : t.rows) r.frames = 2;
    const BudgetPick p = BudgetPicker::pick(t, 0.5, "0");
    ASSERT_EQ(p.lines.size(), 1u);
    EXPECT_NE(p.lines[0].find("ao time 1 ms [0.8, 1.2] (2 counted frame(s): too few frames for an interval)"),
              std::string::npos)
        << p.lines[0];
    for (auto& r : t.rows) r.frames = 6;
    EXPECT_EQ(BudgetPicker::pick(t, 0.5, "0").lines[0].find("too few"), std::string::npos);
}
