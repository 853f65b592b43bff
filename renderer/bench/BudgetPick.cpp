#include "renderer/bench/BudgetPick.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/Error.h"
#include "renderer/OptionText.h"
#include "renderer/metrics/Bootstrap.h"

namespace dw {

namespace {

std::string describe(const TradeoffTable& t, const TradeoffRow& r) {
    std::string s = "point " + std::to_string(r.point);
    std::string values;
    for (size_t a = 0; a < t.axes.size() && a < r.axisValues.size(); ++a)
        values += (values.empty() ? "" : ", ") + t.axes[a] + "=" + r.axisValues[a];
    return values.empty() ? s : s + " (" + values + ")";
}

struct Cost {
    double value = 0.0, lo = 0.0, hi = 0.0;
};

Cost costOf(const BudgetCost& c, const TradeoffRow& r) {
    Cost v;
    c.of(r, v.value, v.lo, v.hi);
    return v;
}

std::string costText(const BudgetCost& c, const TradeoffRow& r) {
    const Cost v = costOf(c, r);
    const std::string value = c.name + " " + figureText(v.value) + " " + c.unit;
    return c.exact ? value : value + " [" + figureText(v.lo) + ", " + figureText(v.hi) + "]";
}

std::string errorText(const TradeoffRow& r) {
    return r.metric + " " + figureText(r.error) + " [" + figureText(r.errorLo) + ", " + figureText(r.errorHi) + "]";
}

std::string pointList(const std::vector<int>& points) {
    std::string s;
    for (size_t i = 0; i < points.size(); ++i)
        s += (i == 0 ? "" : i + 1 == points.size() ? " and " : ", ") + std::to_string(points[i]);
    return s;
}

// The fitting rows' least error (psnr and ssim: the largest); nullptr when none fits.
TradeoffRow* leastError(const std::vector<TradeoffRow*>& fits) {
    TradeoffRow* best = nullptr;
    for (TradeoffRow* r : fits) {
        if (std::isnan(r->error)) continue;
        const double e = TradeoffTable::lowerIsBetter(r->metric) ? r->error : -r->error;
        const double b = best ? (TradeoffTable::lowerIsBetter(best->metric) ? best->error : -best->error) : 0.0;
        if (!best || e < b) best = r;
    }
    return best;
}

// " (2 counted frame(s): too few frames for an interval)" when a measured
// cost's interval comes from fewer frames than an interval needs; "" else.
std::string tooFewText(const BudgetCost& cost, const TradeoffRow& r) {
    if (cost.exact || enoughForInterval(static_cast<size_t>(std::max(r.frames, 0)))) return "";
    return " (" + std::to_string(r.frames) + " counted frame(s): " + kTooFewForInterval + ")";
}

void noneFits(const TradeoffTable& t, const std::vector<TradeoffRow*>& rows, const BudgetCost& cost, BudgetPick& out) {
    const TradeoffRow* cheapest = nullptr;
    for (const TradeoffRow* r : rows)
        if (std::isfinite(costOf(cost, *r).value) && (!cheapest || costOf(cost, *r).value < costOf(cost, *cheapest).value))
            cheapest = r;
    const std::string budget = figureText(out.budgetMs) + " " + cost.unit;
    if (!cheapest) {
        out.lines.push_back("pick: none: no point has a " + cost.name + " to hold against the budget of " + budget);
        return;
    }
    out.cheapest = cheapest->point;
    out.lines.push_back("pick: none fits the budget of " + budget + " (no point's " + cost.name +
                        (cost.exact ? "" : "'s 95% interval") + " ends under it); the cheapest, " + describe(t, *cheapest) + ", takes " +
                        costText(cost, *cheapest) + tooFewText(cost, *cheapest));
}

}  // namespace

void BudgetPicker::check(double budget, const std::string& flag) {
    // The range tradeoff's command line holds the flag to (OptionLimits' kBudgetMs, kBudget), in its words.
    const NumericOption* o = findNumericOption("tradeoff", flag == "--budget-ms" ? "--budget-ms" : "--budget");
    if (!o->holds(budget)) throw Error(optionRefusal(*o, optionNumberText(budget)));
}

BudgetCost BudgetPicker::timeCost(const TradeoffTable& t) {
    return {t.time + " time", "ms", false, [](const TradeoffRow& r, double& v, double& lo, double& hi) {
                v = r.timeMs;
                lo = r.timeMsLo;
                hi = r.timeMsHi;
            }};
}

BudgetCost BudgetPicker::counterCost(const TradeoffTable& t, const std::string& counter) {
    return {t.time + " " + counter, counter, true, [&t, counter](const TradeoffRow& r, double& v, double& lo, double& hi) {
                v = lo = hi = t.costOf(r, t.time, counter);
            }};
}

BudgetPick BudgetPicker::pick(TradeoffTable& t, double budgetMs, const std::string& camera) {
    return pick(t, budgetMs, camera, timeCost(t));
}

std::string BudgetPicker::shownCamera(const TradeoffTable& t) {
    for (const auto& r : t.rows)
        if (r.camera == TradeoffTable::kAllCameras) return r.camera;
    return t.rows.empty() ? std::string() : t.rows.front().camera;
}

BudgetPick BudgetPicker::pick(TradeoffTable& t, double budgetMs, const std::string& camera, const BudgetCost& cost) {
    check(budgetMs, cost.unit == "ms" ? "--budget-ms" : "--budget");
    BudgetPick out;
    out.budgetMs = budgetMs;
    std::vector<TradeoffRow*> rows, fits;
    for (auto& r : t.rows)
        if (r.camera == camera) rows.push_back(&r);
    if (rows.empty())
        throw Error((cost.unit == "ms" ? "--budget-ms" : "--budget") + std::string(": no rows of camera ") + camera +
                    " to pick from");
    for (TradeoffRow* r : rows) {
        const double hi = costOf(cost, *r).hi;
        const bool fit = std::isfinite(hi) && hi < budgetMs && !std::isnan(r->error);
        r->pick = fit ? "fits" : "over";
        if (fit) fits.push_back(r);
    }
    out.fitting = static_cast<int>(fits.size());
    TradeoffRow* best = leastError(fits);
    if (!best) {
        noneFits(t, rows, cost, out);
        return out;
    }
    best->pick = "pick";
    out.point = best->point;
    for (TradeoffRow* r : fits)
        if (r != best && std::find(best->errorTies.begin(), best->errorTies.end(), r->point) != best->errorTies.end()) {
            r->pick = "tied";
            out.tied.push_back(r->point);
        }
    const bool exact = cost.exact;
    // Fewer counted frames than an interval needs: the interval only repeats them, so no confidence is claimed.
    const bool tooFew = !exact && !enoughForInterval(static_cast<size_t>(std::max(best->frames, 0)));
    out.lines.push_back("pick: " + describe(t, *best) + ": " + errorText(*best) + ", " + costText(cost, *best) +
                        ": the least error of the " + std::to_string(out.fitting) + " point(s) whose " +
                        (exact ? cost.name : cost.name + "'s 95% interval") + " ends under the budget of " +
                        figureText(budgetMs) + " " + cost.unit +
                        (exact    ? std::string(" (exact)")
                         : tooFew ? " (" + std::to_string(best->frames) + " counted frame(s): " + kTooFewForInterval +
                                        ", so no confidence that its median is under)"
                                  : std::string(" (97.5% one-sided that its median is under)")));
    const std::string rule = t.frontRules.count(camera) ? " (the front's confidence: " + t.frontRules.at(camera) + ")" : "";
    out.lines.push_back(out.fitting == 1        ? std::string("pick: the only point that fits")
                        : out.tied.empty()      ? "pick: told apart in error from every other point that fits" + rule
                                                : "pick: cannot be told apart in error from point(s) " +
                                                      pointList(out.tied) + ", which fit too" + rule);
    return out;
}

}  // namespace dw
