#include "renderer/bench/BudgetPick.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/Error.h"

namespace dw {

namespace {

std::string shortNumber(double v) {
    if (std::isnan(v)) return "-";
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", v);
    return text;
}

std::string describe(const TradeoffTable& t, const TradeoffRow& r) {
    std::string s = "point " + std::to_string(r.point);
    std::string values;
    for (size_t a = 0; a < t.axes.size() && a < r.axisValues.size(); ++a)
        values += (values.empty() ? "" : ", ") + t.axes[a] + "=" + r.axisValues[a];
    return values.empty() ? s : s + " (" + values + ")";
}

std::string timeText(const TradeoffTable& t, const TradeoffRow& r) {
    return t.time + " " + shortNumber(r.timeMs) + " ms [" + shortNumber(r.timeMsLo) + ", " + shortNumber(r.timeMsHi) + "]";
}

std::string errorText(const TradeoffRow& r) {
    return r.metric + " " + shortNumber(r.error) + " [" + shortNumber(r.errorLo) + ", " + shortNumber(r.errorHi) + "]";
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

void noneFits(const TradeoffTable& t, const std::vector<TradeoffRow*>& rows, BudgetPick& out) {
    const TradeoffRow* cheapest = nullptr;
    for (const TradeoffRow* r : rows)
        if (std::isfinite(r->timeMs) && (!cheapest || r->timeMs < cheapest->timeMs)) cheapest = r;
    const std::string budget = shortNumber(out.budgetMs) + " ms";
    if (!cheapest) {
        out.lines.push_back("pick: none: no point has a " + t.time + " time to hold against the budget of " + budget);
        return;
    }
    out.cheapest = cheapest->point;
    out.lines.push_back("pick: none fits the budget of " + budget + " (no point's 95% time interval ends under it); the cheapest, " +
                        describe(t, *cheapest) + ", takes " + timeText(t, *cheapest));
}

}  // namespace

void BudgetPicker::check(double ms) {
    if (!(std::isfinite(ms) && ms > 0.0))
        throw Error("--budget-ms: expected milliseconds above 0 (a finite number), got " +
                    std::string(std::isnan(ms) ? "nan" : std::isinf(ms) ? (ms > 0 ? "inf" : "-inf") : shortNumber(ms)));
}

std::string BudgetPicker::shownCamera(const TradeoffTable& t) {
    for (const auto& r : t.rows)
        if (r.camera == TradeoffTable::kAllCameras) return r.camera;
    return t.rows.empty() ? std::string() : t.rows.front().camera;
}

BudgetPick BudgetPicker::pick(TradeoffTable& t, double budgetMs, const std::string& camera) {
    check(budgetMs);
    BudgetPick out;
    out.budgetMs = budgetMs;
    std::vector<TradeoffRow*> rows, fits;
    for (auto& r : t.rows)
        if (r.camera == camera) rows.push_back(&r);
    if (rows.empty()) throw Error("--budget-ms: no rows of camera " + camera + " to pick from");
    for (TradeoffRow* r : rows) {
        const bool fit = std::isfinite(r->timeMsHi) && r->timeMsHi < budgetMs && !std::isnan(r->error);
        r->pick = fit ? "fits" : "over";
        if (fit) fits.push_back(r);
    }
    out.fitting = static_cast<int>(fits.size());
    TradeoffRow* best = leastError(fits);
    if (!best) {
        noneFits(t, rows, out);
        return out;
    }
    best->pick = "pick";
    out.point = best->point;
    for (TradeoffRow* r : fits)
        if (r != best && std::find(best->errorTies.begin(), best->errorTies.end(), r->point) != best->errorTies.end()) {
            r->pick = "tied";
            out.tied.push_back(r->point);
        }
    out.lines.push_back("pick: " + describe(t, *best) + ": " + errorText(*best) + ", " + timeText(t, *best) +
                        ": the least error of the " + std::to_string(out.fitting) +
                        " point(s) whose 95% time interval ends under the budget of " + shortNumber(budgetMs) +
                        " ms (97.5% one-sided that its median time is under)");
    out.lines.push_back(out.tied.empty()
                            ? "pick: told apart in error from every other point that fits"
                            : "pick: cannot be told apart in error from point(s) " + pointList(out.tied) +
                                  ", which fit too (the front's confidence: " +
                                  (t.frontRules.count(camera) ? t.frontRules.at(camera) : std::string("?")) + ")");
    return out;
}

}  // namespace dw
