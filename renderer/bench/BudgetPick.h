#pragma once
// A budget that picks (issue 34, mission row 64): of a tradeoff table's
// points, the one with the least error whose time's 95% interval ends under
// the budget (its upper end below it: the median time is under the budget
// with 97.5% one-sided confidence), and the points that fit too but cannot
// be told apart from it in error (ConfidentFront's error order, at its
// familywise confidence). None fits: the cheapest point by median time, with
// its interval. The time is the table's `time` (time_ms: frame, a pass or a
// sum of passes). Marks the rows' `pick` column. Needs no GL.
#include <functional>
#include <string>
#include <vector>

#include "renderer/bench/TradeoffTable.h"

namespace dw {

struct BudgetPick {
    double budgetMs = 0.0;
    int point = -1;          // the pick's point number; -1 when none fits
    std::vector<int> tied;   // points that fit and are not told apart from the pick in error
    int fitting = 0;         // how many points fit
    int cheapest = -1;       // with none fitting: the point with the least median time (-1: no time at all)
    std::vector<std::string> lines;  // what tradeoff prints, each starting "pick:"
};

// What a budget bounds in a row: a cost with its 95% interval (hi is what
// must be under the budget), named and in a unit for the lines ("ao", "ms").
// The time (time_ms) by default; a counter (issue 34's --cost) gives its own,
// exact (lo == hi == value).
struct BudgetCost {
    std::string name, unit;  // "ao time", "ms"
    bool exact = false;      // no interval: the value itself is held against the budget
    std::function<void(const TradeoffRow&, double& value, double& lo, double& hi)> of;
};

class BudgetPicker {
public:
    // Throws dw::Error (one line, the command line's own refusal: "--budget-ms
    // must be a number above 0 and at most 1000000000 (GPU milliseconds), got
    // '0'") unless the budget is in tradeoff's range for `flag` (--budget-ms:
    // OptionLimits' kBudgetMs; --budget: kBudget). Python and the window check
    // through here, so they refuse what the CLI refuses, in the same words.
    static void check(double budget, const std::string& flag = "--budget-ms");
    // The pick among the rows of `camera` ("all" for several cameras) by
    // the table's time (time_ms); sets those rows' pick (pick | tied | fits |
    // over). Throws Error when the table has no such rows.
    static BudgetPick pick(TradeoffTable& table, double budgetMs, const std::string& camera);
    // The same over any cost of a row.
    static BudgetPick pick(TradeoffTable& table, double budget, const std::string& camera, const BudgetCost& cost);
    // The table's time as a BudgetCost (time_ms and its interval, in ms).
    static BudgetCost timeCost(const TradeoffTable& table);
    // A counter of the table's time span (TradeoffTable::costOf: `tradeoff
    // --cost fragments --budget N`) as a BudgetCost: exact, in its own unit
    // ("fragments", "bytes", ...).
    static BudgetCost counterCost(const TradeoffTable& table, const std::string& counter);
    // The camera whose rows a summary shows: "all" when the table has such rows, else the first row's.
    static std::string shownCamera(const TradeoffTable& table);
};

}  // namespace dw
