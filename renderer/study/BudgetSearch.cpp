#include "renderer/study/BudgetSearch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>

#include "renderer/Error.h"
#include "renderer/OptionText.h"
#include "renderer/OptionLimits.h"
#include "renderer/study/CachedReferences.h"

namespace dw {

namespace {

bool asNumber(const std::string& text, double& v) {
    char* end = nullptr;
    v = std::strtod(text.c_str(), &end);
    return !text.empty() && end && *end == '\0' && std::isfinite(v);
}

// A walked knob: its values in walking order (numbers sorted, else as the sweep has them).
struct Axis {
    std::string name;
    std::vector<std::string> values;
    bool ordered = false;  // every value a number: neighbours are the next smaller and larger
    size_t at = 0;         // the current value
};

std::vector<Axis> searchAxes(const TradeoffSweep& sweep) {
    std::vector<Axis> axes;
    for (size_t i = 0; i < sweep.axes.size(); ++i) {
        Axis a{sweep.axes[i].name, sweep.axes[i].values};
        double v = 0.0;
        a.ordered = std::all_of(a.values.begin(), a.values.end(), [&](const std::string& t) { return asNumber(t, v); });
        if (a.ordered)
            std::stable_sort(a.values.begin(), a.values.end(), [](const std::string& x, const std::string& y) {
                double vx = 0.0, vy = 0.0;
                asNumber(x, vx);
                asNumber(y, vy);
                return vx < vy;
            });
        const std::string centre = i < sweep.centre.size() ? sweep.centre[i] : a.values.front();
        a.at = static_cast<size_t>(std::find(a.values.begin(), a.values.end(), centre) - a.values.begin());
        if (a.at >= a.values.size()) a.at = 0;
        axes.push_back(std::move(a));
    }
    return axes;
}

// The candidate positions of a step on `a`: after a move the next one the same way, else both neighbours (names: every other).
std::vector<size_t> candidates(const Axis& a, int direction) {
    std::vector<size_t> out;
    const long at = static_cast<long>(a.at), n = static_cast<long>(a.values.size());
    if (a.ordered && direction != 0) {
        if (at + direction >= 0 && at + direction < n) out.push_back(static_cast<size_t>(at + direction));
        return out;
    }
    for (long i = 0; i < n; ++i)
        if (i != at && (!a.ordered || i == at - 1 || i == at + 1)) out.push_back(static_cast<size_t>(i));
    return out;
}

// One step's run: every knob at its current value, `stepped` also at the candidates (point 0: the current settings).
TradeoffOptions stepOptions(const TradeoffOptions& base, const std::vector<Axis>& axes, size_t stepped,
                            const std::vector<size_t>& cands) {
    TradeoffOptions o = base;
    o.sweep = TradeoffSweep{};
    for (size_t i = 0; i < axes.size(); ++i) {
        TradeoffAxis axis{axes[i].name, {axes[i].values[axes[i].at]}, {}};
        if (i == stepped)
            for (size_t c : cands) axis.values.push_back(axes[i].values[c]);
        o.sweep.axes.push_back(std::move(axis));
    }
    o.shard = BenchShard{};
    return o;
}

// The cost the budget bounds (time, or --budget's counter).
BudgetCost budgetCost(const TradeoffOptions& o, const TradeoffTable& t) {
    return o.budget > 0.0 ? BudgetPicker::counterCost(t, o.cost) : BudgetPicker::timeCost(t);
}

struct Measured {
    TradeoffTable table;
    int step = 0, firstEvaluation = 0;
    std::vector<std::string> proposals;  // per local point
};

struct Decision {
    int moveTo = -1;  // local point; -1: stay
    std::string why;
};

// The move a step's run supports (the header's rule). `relaxed`: with
// nothing fitting, a cheaper candidate is taken even when its error is
// worse (after a whole round of knobs found no other way toward the budget).
Decision decide(const TradeoffOptions& o, TradeoffTable& t, const BudgetPick& pick, bool relaxed) {
    const std::string camera = BudgetPicker::shownCamera(t);
    std::map<int, const TradeoffRow*> rows;
    for (const auto& r : t.rows)
        if (r.camera == camera) rows[r.point] = &r;
    const TradeoffRow* current = rows.count(0) ? rows[0] : nullptr;
    if (!current) return {-1, "the current settings were not measured"};
    if (pick.point == 0) return {-1, "the current value is the pick"};
    if (pick.point > 0) {
        if (current->pick == "over") return {pick.point, "fits the budget where the current value does not"};
        if (current->pick == "tied")
            return {-1, "could not tell: the pick's error is not told apart from the current value's"};
        return {pick.point, "less error, told apart from the current value's, within the budget"};
    }
    // Nothing fits: toward the budget, the cheapest candidate whose error is no worse.
    const BudgetCost cost = budgetCost(o, t);
    const bool lower = TradeoffTable::lowerIsBetter(current->metric);
    // No worse: its error at most the current value's (psnr, ssim: at least); the errors are the images' own,
    // deterministic, so a saving that only ties in error is not taken before a whole round found none better.
    auto worse = [&](const TradeoffRow& r) { return lower ? r.error > current->error : r.error < current->error; };
    double v = 0.0, lo = 0.0, hi = 0.0, now = 0.0;
    cost.of(*current, now, lo, hi);
    int cheapest = -1;
    double least = std::isfinite(now) ? now : std::numeric_limits<double>::infinity();
    bool skipped = false;
    for (const auto& [point, r] : rows) {
        cost.of(*r, v, lo, hi);
        if (point == 0 || !std::isfinite(v) || v >= least) continue;
        if (!relaxed && worse(*r)) {
            skipped = true;
            continue;
        }
        least = v;
        cheapest = point;
    }
    if (cheapest < 0)
        return {-1, skipped ? "nothing fits the budget; the cheaper candidates' error is worse"
                            : "nothing fits the budget and no candidate is cheaper"};
    return {cheapest, "nothing fits the budget yet: toward it, the cheapest candidate" +
                          std::string(relaxed ? "" : " whose error is no worse") + " (" + cost.name + " " +
                          figureText(least) + " " + cost.unit + " against " + figureText(now) + ")"};
}

// Whether the step's row of `point` (local) fits its budget (its pick column).
bool currentFits(const TradeoffTable& t, int point) {
    const std::string camera = BudgetPicker::shownCamera(t);
    for (const auto& r : t.rows)
        if (r.camera == camera && r.point == point) return r.pick == "pick" || r.pick == "tied" || r.pick == "fits";
    return false;
}

// Every step's rows in one table: point = evaluation, the axes step and proposal first, the passes' union.
TradeoffTable joined(const std::vector<Measured>& runs, const std::vector<Axis>& axes, const std::string& time) {
    TradeoffTable all;
    all.time = time;
    all.axes = {"step", "proposal"};
    for (const Axis& a : axes) all.axes.push_back(a.name);
    for (const Measured& m : runs) {
        for (const auto& p : m.table.passes)
            if (std::find(all.passes.begin(), all.passes.end(), p) == all.passes.end()) all.passes.push_back(p);
        all.counted = all.counted || m.table.counted;
    }
    CounterValues none;
    none.fill(std::numeric_limits<double>::quiet_NaN());
    for (const Measured& m : runs) {
        auto renumber = [&](std::vector<int>& points) {
            for (int& p : points) p += m.firstEvaluation;
        };
        for (TradeoffRow r : m.table.rows) {
            const std::string proposal =
                r.point >= 0 && static_cast<size_t>(r.point) < m.proposals.size() ? m.proposals[r.point] : "";
            r.axisValues.insert(r.axisValues.begin(), {std::to_string(m.step), proposal});
            r.point += m.firstEvaluation;
            renumber(r.dominatedBy);
            renumber(r.errorTies);
            renumber(r.timeTies);
            for (auto& tie : r.tiedWith) tie.first += m.firstEvaluation;
            std::vector<double> ms(all.passes.size(), std::numeric_limits<double>::quiet_NaN());
            std::vector<CounterValues> counts(all.passes.size(), none);
            for (size_t i = 0; i < m.table.passes.size(); ++i) {
                const size_t at = static_cast<size_t>(
                    std::find(all.passes.begin(), all.passes.end(), m.table.passes[i]) - all.passes.begin());
                if (i < r.passGpuMs.size()) ms[at] = r.passGpuMs[i];
                if (i < r.passCounts.size()) counts[at] = r.passCounts[i];
            }
            r.passGpuMs = std::move(ms);
            r.passCounts = std::move(counts);
            all.rows.push_back(std::move(r));
        }
    }
    return all;
}

std::string settingsText(const std::vector<Axis>& axes, const std::vector<size_t>& start) {
    std::string changed;
    for (size_t i = 0; i < axes.size(); ++i)
        if (axes[i].at != start[i]) changed += (changed.empty() ? "" : ", ") + axes[i].name + "=" + axes[i].values[axes[i].at];
    return changed.empty() ? "the current settings (no knob moved)" : changed + " (every other knob as it was)";
}

// The lines after the steps: what it found, its intervals, the evaluations.
void summarise(const BudgetSearchOptions& so, const std::vector<Axis>& axes, const std::vector<size_t>& start,
               BudgetSearchResult& r) {
    const TradeoffOptions& o = so.base;
    r.lines.push_back("search: found " + settingsText(axes, start));
    const TradeoffRow* row = nullptr;
    for (const auto& x : r.table.rows)
        if (x.point == r.foundEvaluation && x.camera == BudgetPicker::shownCamera(r.table)) row = &x;
    if (row) {
        const BudgetCost cost = budgetCost(o, r.table);
        double v = 0.0, lo = 0.0, hi = 0.0;
        cost.of(*row, v, lo, hi);
        const std::string budget = figureText(o.budget > 0.0 ? o.budget : o.budgetMs) + " " + cost.unit;
        r.fits = row->pick == "pick" || row->pick == "tied" || row->pick == "fits";
        r.lines.push_back("search: evaluation " + std::to_string(r.foundEvaluation) + ": " + row->metric + " " +
                          figureText(row->error) + " [" + figureText(row->errorLo) + ", " + figureText(row->errorHi) +
                          "], " + cost.name + " " + figureText(v) + " " + cost.unit +
                          (cost.exact ? " (exact)" : " [" + figureText(lo) + ", " + figureText(hi) + "]") + ": " +
                          (r.fits ? "fits" : "does not fit") + " the budget of " + budget +
                          (cost.exact ? "" : " (its 95% interval's upper end against it)"));
    }
    r.lines.push_back("search: " + std::to_string(r.evaluations) + " evaluation(s) in " + std::to_string(r.steps.size()) +
                      " step(s) (bound " + std::to_string(so.maxEvals) + "), " +
                      (r.converged ? "converged: no knob moved in its last step"
                                   : "stopped at the bound: the next step would pass it") +
                      "; the grid of --knobs speed/quality about the same start has " + std::to_string(r.gridPoints) +
                      " point(s)");
}

}  // namespace

void BudgetSearch::checkMaxEvals(int n) {
    if (!limits::kMaxEvals.holds(n))
        throw Error("--max-evals must be between " + std::to_string(limits::kMaxEvals.min) + " and " +
                    std::to_string(limits::kMaxEvals.max) + ", got " + std::to_string(n));
}

TradeoffResult BudgetSearch::asResult(const BudgetSearchResult& found) {
    TradeoffResult result = found.last;
    result.table = found.table;
    std::string settings;
    for (size_t k = 0; k < found.knobs.size(); ++k)
        settings += (k ? " " : "") + found.knobs[k] + "=" + found.found[k];
    result.settings.emplace_back("search_evaluations", std::to_string(found.evaluations));
    result.settings.emplace_back("search_found_evaluation", std::to_string(found.foundEvaluation));
    result.settings.emplace_back("search_found", settings);
    result.settings.emplace_back("search_fits", found.fits ? "1" : "0");
    result.settings.emplace_back("references_rendered", std::to_string(found.referencesRendered));
    result.settings.emplace_back("references_from_cache", std::to_string(found.referencesFromCache));
    return result;
}

namespace {

// Where the walk stands: the knobs (each at its current value), the one stepped next and how it last moved.
struct Walk {
    std::vector<Axis> axes;
    size_t axis = 0;
    int direction = 0;      // after a move along a knob of numbers: +1 or -1, the way it went
    size_t stillSteps = 0;  // steps without a move since the last move
    bool relaxed = false;   // nothing fits after a round of knobs without a move: cheaper whatever the error
    void next() {
        axis = (axis + 1) % axes.size();
        direction = 0;
    }
};

// One step: the current settings and `cands` of the stepped knob in one run; its rows as `m`.
TradeoffResult measureStep(const BudgetSearchOptions& so, const Walk& w, const std::vector<size_t>& cands,
                           const TradeoffReference& reference, const std::function<void(const std::string&)>& say,
                           const std::function<void(const std::string&)>& warn, BudgetSearchStep& step, Measured& m) {
    const Axis& a = w.axes[w.axis];
    std::string values;
    m.step = step.step;
    m.firstEvaluation = step.firstEvaluation;
    for (size_t c : cands) {
        step.values.push_back(a.values[c]);
        m.proposals.push_back(a.name + "=" + a.values[c]);
        values += (values.empty() ? "" : ", ") + a.values[c];
    }
    say("search: step " + std::to_string(step.step) + ": " + a.name + " " + a.values[a.at] + " against " + values);
    TradeoffRunner runner(stepOptions(so.base, w.axes, w.axis, cands));
    runner.setWarningSink(warn);
    TradeoffResult result = runner.run(reference, say);
    m.table = result.table;
    return result;
}

// The step's decision applied to the walk: the knob moved (and the walk goes on along it) or kept.
void applyDecision(Walk& w, const std::vector<size_t>& cands, const Decision& d, BudgetSearchStep& step,
                   int& foundEvaluation) {
    Axis& a = w.axes[w.axis];
    const std::string from = a.values[a.at];
    if (d.moveTo <= 0) {
        foundEvaluation = step.firstEvaluation;
        step.outcome = "kept " + a.name + "=" + from + ": " + d.why;
        ++w.stillSteps;
        w.next();
        return;
    }
    const size_t to = cands[static_cast<size_t>(d.moveTo - 1)];
    const int direction = a.ordered ? (to > a.at ? 1 : -1) : 0;
    a.at = to;
    foundEvaluation = step.firstEvaluation + d.moveTo;
    step.outcome = "moved " + a.name + " " + from + " -> " + a.values[a.at] + ": " + d.why;
    w.stillSteps = 0;
    if (a.ordered)
        w.direction = direction;  // the same knob again, one further the same way
    else
        w.next();
}

}  // namespace

BudgetSearchResult BudgetSearch::run(const BudgetSearchOptions& so, const TradeoffStudyProgress& progress) {
    checkMaxEvals(so.maxEvals);
    if (!(so.base.budgetMs > 0.0) && !(so.base.budget > 0.0))
        throw Error("--search needs a budget: --budget-ms X (or --budget N with --cost fragments|...)");
    auto stopIfAsked = [&] {
        if (progress.cancelled && progress.cancelled()) throw TradeoffCancelled();
    };
    const std::function<void(const std::string&)> say = [&](const std::string& line) {
        stopIfAsked();
        if (progress.line) progress.line(line);
    };
    const std::function<void(const std::string&)> warn = [&](const std::string& line) {
        if (progress.warning) progress.warning(line);
    };
    Walk w;
    w.axes = searchAxes(so.base.sweep);
    if (w.axes.empty()) throw Error("--search: no speed/quality knob to walk at these settings");
    std::vector<size_t> start;
    for (const Axis& a : w.axes) start.push_back(a.at);
    CachedReferences references(so.aoRays, so.referenceSeed, {say, warn, stopIfAsked}, so.referencePixels);
    const TradeoffReference reference = references.function();

    BudgetSearchResult r;
    r.gridPoints = so.base.sweep.count();
    std::vector<Measured> runs;
    for (;;) {
        if (w.stillSteps >= w.axes.size()) {  // a round of knobs without a move
            const bool fits = !runs.empty() && currentFits(runs.back().table, r.foundEvaluation - runs.back().firstEvaluation);
            if (fits || w.relaxed) break;
            w.relaxed = true;
            w.stillSteps = 0;
            say("search: nothing fits after a round of every knob: toward the budget whatever the error");
        }
        const std::vector<size_t> cands = candidates(w.axes[w.axis], w.direction);
        if (cands.empty()) {  // the end of the knob the way it moved: the next knob
            w.next();
            continue;
        }
        const int cost = 1 + static_cast<int>(cands.size());
        if (r.evaluations + cost > so.maxEvals) {
            if (r.steps.empty())
                throw Error("--max-evals " + std::to_string(so.maxEvals) + ": the first step alone takes " +
                            std::to_string(cost) + " evaluations (the current settings and " + w.axes[w.axis].name +
                            "'s candidates)");
            break;
        }
        BudgetSearchStep step{static_cast<int>(r.steps.size()) + 1, w.axes[w.axis].name, {}, r.evaluations, cost, ""};
        Measured m;
        m.proposals.push_back(runs.empty() ? "start" : "current");
        r.last = measureStep(so, w, cands, reference, say, warn, step, m);
        const Decision d = decide(so.base, m.table, r.last.pick, w.relaxed);
        r.evaluations += cost;
        runs.push_back(std::move(m));
        applyDecision(w, cands, d, step, r.foundEvaluation);
        r.lines.push_back("search: step " + std::to_string(step.step) + " (evaluations " +
                          std::to_string(step.firstEvaluation) + "-" +
                          std::to_string(step.firstEvaluation + step.evaluations - 1) + "): " + step.outcome);
        say(r.lines.back());
        r.steps.push_back(std::move(step));
    }
    r.converged = w.stillSteps >= w.axes.size();
    for (const Axis& a : w.axes) {
        r.knobs.push_back(a.name);
        r.found.push_back(a.values[a.at]);
    }
    r.table = joined(runs, w.axes, so.base.time);
    r.referencesRendered = references.rendered();
    r.referencesFromCache = references.fromCache();
    summarise(so, w.axes, start, r);
    return r;
}

}  // namespace dw
