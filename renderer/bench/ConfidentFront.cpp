#include "renderer/bench/ConfidentFront.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "renderer/Error.h"
#include "renderer/bench/ParetoFront.h"

namespace dw {

namespace {

bool usable(const FrontEvidence& e) {
    return std::isfinite(e.cost.value) && !std::isnan(e.error.value) && e.error.value != HUGE_VAL;
}

Order flipped(Order o) {
    if (o == Order::firstBetter) return Order::secondBetter;
    if (o == Order::secondBetter) return Order::firstBetter;
    return o;
}

// A comparison waiting for the adjustment: the pair, the axis, its test.
struct PendingTest {
    size_t i = 0, j = 0;
    bool time = false;
    PairedTest test;
};

// One axis of one pair without the adjustment: decided now, or (draws) pending.
Order compareAxis(const FrontAxis& a, const FrontAxis& b, FrontRule rule, bool& pending, PairedTest& test) {
    pending = false;
    if (a.exact && b.exact)
        return a.value < b.value ? Order::firstBetter : b.value < a.value ? Order::secondBetter : Order::identical;
    if (rule == FrontRule::pairedBootstrap) {
        if (a.draws.empty() || a.draws.size() != b.draws.size()) return Order::notApart;
        test = pairedTest(a.draws, b.draws);
        if (test.identical && a.value == b.value) return Order::identical;
        pending = true;
        return Order::notApart;
    }
    if (a.value == b.value && a.lo == b.lo && a.hi == b.hi) return Order::identical;
    if (!std::isfinite(a.lo) || !std::isfinite(a.hi) || !std::isfinite(b.lo) || !std::isfinite(b.hi)) return Order::notApart;
    if (a.hi < b.lo) return Order::firstBetter;
    if (b.hi < a.lo) return Order::secondBetter;
    return Order::notApart;
}

// Every pair's order on both axes; the draws' tests adjusted together (Holm).
void orderPairs(const std::vector<FrontEvidence>& pts, const std::vector<bool>& ok, FrontRule rule, double alpha,
                FrontDecision& d) {
    const size_t n = pts.size();
    d.timeOrder.assign(n, std::vector<Order>(n, Order::notApart));
    d.errorOrder.assign(n, std::vector<Order>(n, Order::notApart));
    std::vector<PendingTest> pending;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            if (!ok[i] || !ok[j]) continue;
            for (bool time : {true, false}) {
                bool waits = false;
                PairedTest t;
                const Order o = time ? compareAxis(pts[i].cost, pts[j].cost, rule, waits, t)
                                     : compareAxis(pts[i].error, pts[j].error, rule, waits, t);
                auto& order = time ? d.timeOrder : d.errorOrder;
                order[i][j] = o;
                order[j][i] = flipped(o);
                if (waits) pending.push_back({i, j, time, t});
                else if (o == Order::notApart) ++(time ? d.untestedTime : d.untestedError);
                if (waits) ++(time ? d.testedTime : d.testedError);
                if (time && pts[i].cost.exact && pts[j].cost.exact) ++d.exactCost;
            }
        }
    std::vector<double> p;
    for (const auto& t : pending) p.push_back(t.test.p);
    const std::vector<bool> rejected = holmRejects(p, alpha);
    for (size_t k = 0; k < pending.size(); ++k) {
        if (!rejected[k] || pending[k].test.favours == 0) continue;
        const Order o = pending[k].test.favours < 0 ? Order::firstBetter : Order::secondBetter;
        auto& order = pending[k].time ? d.timeOrder : d.errorOrder;
        order[pending[k].i][pending[k].j] = o;
        order[pending[k].j][pending[k].i] = flipped(o);
    }
    d.comparisons = static_cast<int>(pending.size());
    d.draws = 0;
    for (const auto& t : pending) {
        const FrontAxis& a = t.time ? pts[t.i].cost : pts[t.i].error;
        if (d.draws == 0 || static_cast<int>(a.draws.size()) < d.draws) d.draws = static_cast<int>(a.draws.size());
    }
}

bool notWorse(Order o) { return o == Order::firstBetter || o == Order::identical; }

// q (first) confidently dominates p (second).
bool dominates(const FrontDecision& d, size_t q, size_t p) {
    const Order t = d.timeOrder[q][p], e = d.errorOrder[q][p];
    return notWorse(t) && notWorse(e) && (t == Order::firstBetter || e == Order::firstBetter);
}

bool tiedOn(Order o) { return o == Order::notApart || o == Order::identical; }

std::string percent(double alpha) {
    const double c = 100.0 * (1.0 - alpha);
    const double r = std::round(c);
    return (std::abs(c - r) < 1e-9 ? std::to_string(static_cast<int>(r)) : std::to_string(c)) + "%";
}

std::string untestedText(const FrontDecision& d) {
    std::string s;
    for (const auto& [axis, n] : {std::make_pair("time", d.untestedTime), std::make_pair("error", d.untestedError)})
        if (n > 0)
            s += "; " + std::string(axis) + " not tested for " + std::to_string(n) +
                 " pair(s) (no resamples: fewer than 6 rounds, or a value missing), so not told apart there";
    return s;
}

// Said when the draws are too few for Holm's first step: the smallest p-value
// a pair can reach, 2 / (B + 1), is above alpha / m, so no pair is told apart.
std::string floorText(const FrontDecision& d, double alpha) {
    if (d.comparisons == 0 || d.draws == 0) return "";
    const double smallest = 2.0 / (d.draws + 1.0), first = alpha / d.comparisons;
    if (smallest <= first) return "";
    return "; at " + std::to_string(d.draws) + " resamples the smallest p-value a pair can reach (" +
           std::to_string(smallest) + ") is above Holm's first threshold (" + std::to_string(first) +
           "), so no pair can be told apart: use --resamples " +
           std::to_string(frontDrawsNeeded(d.comparisons, alpha)) + " or more";
}

// Which axes the adjustment covered: "every pair of points, on each axis",
// or the pairs per axis and why an axis was not (a counter; no resamples).
std::string testedText(const FrontDecision& d) {
    if (d.testedTime > 0 && d.testedTime == d.testedError) return "every pair of points, on each axis";
    if (d.testedTime == 0 && d.testedError == 0) return "no pair had paired resamples";
    std::string s;
    for (const auto& [axis, n] : {std::make_pair("time", d.testedTime), std::make_pair("error", d.testedError)})
        if (n > 0) s += (s.empty() ? "" : ", ") + std::to_string(n) + " pair(s) on " + axis;
    if (d.testedTime == 0)
        s += d.exactCost > 0 ? std::string(" only; the cost, an exact counter, compared by value")
                             : std::string(" only; time not tested");
    return s;
}

std::string ruleText(FrontRule rule, double alpha, const FrontDecision& d) {
    const int comparisons = d.comparisons, draws = d.draws;
    if (rule == FrontRule::intervals)
        return "from the rows' " + percent(alpha) +
               " intervals: a point beats another on an axis only where their intervals do not overlap "
               "(no resamples carried; not adjusted for the number of comparisons)";
    return percent(alpha) + " familywise: paired bootstrap (time: the interleaved rounds resampled together; "
           "error: the same resampled tiles), Holm's step-down over " + std::to_string(comparisons) +
           " comparison(s) (" + testedText(d) + ")" +
           (draws > 0 ? " from " + std::to_string(draws) + " paired resamples" : std::string());
}

}  // namespace

std::string FrontTie::axes() const { return time && error ? "time,error" : time ? "time" : "error"; }

bool FrontDecision::errorTied(size_t i, size_t j) const { return tiedOn(errorOrder[i][j]); }

PairedTest pairedTest(const std::vector<double>& a, const std::vector<double>& b) {
    PairedTest t;
    const size_t n = std::min(a.size(), b.size());
    size_t lower = 0, higher = 0;  // draws where a < b, a > b (equal draws: neither; inf == inf is equal)
    for (size_t k = 0; k < n; ++k) {
        if (a[k] < b[k]) ++lower;
        else if (a[k] > b[k]) ++higher;
    }
    const size_t equal = n - lower - higher;
    t.identical = n > 0 && equal == n;
    if (n == 0 || t.identical) return t;
    // #{d >= 0} = higher + equal, #{d <= 0} = lower + equal.
    const double tail = static_cast<double>(std::min(higher, lower) + equal);
    t.p = std::min(1.0, 2.0 * (tail + 1.0) / (static_cast<double>(n) + 1.0));
    t.favours = lower > higher ? -1 : higher > lower ? 1 : 0;
    return t;
}

int frontDrawsNeeded(int comparisons, double alpha) {
    if (comparisons <= 0 || !(alpha > 0.0 && alpha < 1.0)) return 0;
    // 2 / (B + 1) <= alpha / (2 m): a p-value of half Holm's first threshold
    // is reachable, so a clear difference is not lost to the draws' floor.
    return static_cast<int>(std::ceil(4.0 * comparisons / alpha));
}

std::vector<bool> holmRejects(const std::vector<double>& p, double alpha) {
    std::vector<size_t> order(p.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
    std::vector<bool> rejected(p.size(), false);
    const double m = static_cast<double>(p.size());
    for (size_t k = 0; k < order.size(); ++k) {
        if (!(p[order[k]] <= alpha / (m - static_cast<double>(k)))) break;  // stop at the first kept
        rejected[order[k]] = true;
    }
    return rejected;
}

FrontDecision decideFront(const std::vector<FrontEvidence>& pts, FrontRule rule, double alpha) {
    if (pts.empty()) throw Error("no points to compare: the sweep is empty");
    if (!(alpha > 0.0 && alpha < 1.0)) throw Error("the front's familywise error must be in (0, 1)");
    const size_t n = pts.size();
    FrontDecision d;
    std::vector<bool> ok(n);
    std::vector<ParetoPoint> estimates;
    for (size_t i = 0; i < n; ++i) {
        ok[i] = usable(pts[i]);
        estimates.push_back({pts[i].cost.value, pts[i].error.value});
    }
    const ParetoFront front(estimates);
    orderPairs(pts, ok, rule, alpha, d);
    d.front.assign(n, "");
    d.dominatedBy.assign(n, {});
    d.tiedWith.assign(n, {});
    for (size_t p = 0; p < n; ++p) {
        if (!ok[p]) continue;
        if (front.contains(p)) {
            d.front[p] = "pareto";
            continue;
        }
        for (size_t q : front.members())
            if (dominates(d, q, p)) d.dominatedBy[p].push_back(q);
        d.front[p] = d.dominatedBy[p].empty() ? "indistinguishable" : "dominated";
    }
    for (size_t p = 0; p < n; ++p)
        for (size_t q = 0; q < n; ++q) {
            if (p == q || !ok[p] || !ok[q] || d.front[p] == "dominated" || d.front[q] == "dominated") continue;
            FrontTie tie{q, tiedOn(d.timeOrder[p][q]), tiedOn(d.errorOrder[p][q])};
            if (tie.time || tie.error) d.tiedWith[p].push_back(tie);
        }
    d.rule = ruleText(rule, alpha, d) +
             (rule == FrontRule::pairedBootstrap ? untestedText(d) + floorText(d, alpha) : "");
    return d;
}

}  // namespace dw
