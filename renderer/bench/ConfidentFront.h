#pragma once
// Which points of a time/error trade can be told apart: the Pareto front of
// the point estimates (ParetoFront), and which of the other points another
// point beats on both axes with a stated confidence. `tradeoff` marks its
// rows' `front`, `dominated_by` and `tied_with` with it (docs/tradeoffs.md,
// "How the front is decided").
//
// Each point has a cost (time; any minimised number: the caller says which,
// so a counter can be the cost) and an error (minimised: flip psnr and ssim
// before), each as a point estimate and either
//   - draws: B values of the statistic recomputed on resampled data, where
//     draw b of every point used the same resample (paired: the same rounds
//     of the interleaved timing, the same tiles of the image), or
//   - exact: no draws; the value is the quantity itself (a counter), or
//   - an interval only (lo, hi): `tradeoff merge`, which has no draws.
//
// Per pair (i, j) and axis, the comparison:
//   draws      d_b = x_i[b] - x_j[b]. Every d_b == 0 (and equal estimates):
//              identical. Else a two-sided bootstrap test, its p-value
//              p = min(1, 2 (min(#{d_b >= 0}, #{d_b <= 0}) + 1) / (B + 1)),
//              adjusted by Holm's step-down over every (pair, axis) tested in
//              the set of points (familywise error alpha); rejected: the side
//              most draws favour is better.
//   exact      the smaller is better; equal: identical.
//   intervals  i is better when hi_i < lo_j (the intervals do not
//              overlap); identical when value, lo and hi are all equal; not
//              adjusted for the number of comparisons.
//   mixed      (one side exact, the other not, or a missing value): not told apart.
// q confidently dominates p when, on both axes, q is better or identical, and
// better on at least one. An identical error counts as "not worse".
//
// Classes, for a point with a finite cost and an error that is not NaN/+inf:
//   pareto             on the front of the point estimates (ParetoFront)
//   dominated          off it, and confidently dominated by a pareto point
//                      (dominatedBy: those points)
//   indistinguishable  off it, and no pareto point confidently dominates it
// tiedWith: for a point that is not dominated, the other non-dominated points
// it cannot be told apart from on at least one axis (identical, or not
// decided), each with the axes ("time", "error", or both).
// Needs no GL.
#include <cstddef>
#include <string>
#include <vector>

namespace dw {

struct FrontAxis {
    double value = 0.0;          // the point estimate (minimised)
    double lo = 0.0, hi = 0.0;   // its interval (the intervals rule)
    std::vector<double> draws;   // paired resamples; empty: exact or intervals only
    bool exact = false;          // no draws and none needed: a count, a deterministic quantity
};

struct FrontEvidence {
    FrontAxis cost, error;
};

enum class FrontRule { pairedBootstrap, intervals };

// One pair's comparison on one axis.
enum class Order : signed char { notApart, firstBetter, secondBetter, identical };

struct FrontTie {
    size_t other = 0;  // the point's index
    bool time = false, error = false;  // the axes on which the two are not told apart
    std::string axes() const;          // "time", "error" or "time,error"
};

struct FrontDecision {
    std::vector<std::string> front;                 // "pareto" | "indistinguishable" | "dominated" | "" (no cost or error)
    std::vector<std::vector<size_t>> dominatedBy;   // per point
    std::vector<std::vector<FrontTie>> tiedWith;    // per point
    // order[i][j] per axis: firstBetter when i is confidently better than j, secondBetter when j is.
    std::vector<std::vector<Order>> timeOrder, errorOrder;
    int comparisons = 0;  // (pair, axis) tests that entered the adjustment
    int draws = 0;        // the fewest paired resamples among those tests (0: none)
    int untestedTime = 0, untestedError = 0;  // pairs of usable points with no test on that axis (not told apart)
    int testedTime = 0, testedError = 0;      // pairs whose draws' test entered the adjustment, per axis
    int exactCost = 0;                        // pairs compared by value on the cost axis (both exact: counters)
    std::string rule;     // how it was decided, one line ("95% familywise, Holm over 12 ...")

    // Whether i and j cannot be told apart on error (identical, or not decided).
    bool errorTied(size_t i, size_t j) const;
};

// Throws dw::Error when `points` is empty. alpha in (0, 1): the familywise error.
FrontDecision decideFront(const std::vector<FrontEvidence>& points, FrontRule rule, double alpha = 0.05);

// The one comparison of the draws rule, for tests: the two-sided p-value of
// a - b (1 when every draw is identical), and which side the draws favour
// (-1: a lower, +1: b lower, 0: identical or even).
struct PairedTest {
    double p = 1.0;
    int favours = 0;
    bool identical = false;
};
PairedTest pairedTest(const std::vector<double>& a, const std::vector<double>& b);

// The paired resamples B for which Holm's adjustment over `comparisons`
// tests can reject at all, with room: the bootstrap p-value's floor
// 2 / (B + 1) is at most half of Holm's first threshold alpha / m, so
// B = ceil(4 m / alpha) (m = 72 at alpha 0.05: 5760). 0 for no comparisons.
// Fewer draws than this and the rule line says no pair can be told apart.
int frontDrawsNeeded(int comparisons, double alpha);

// Holm's step-down: for p-values, which are rejected at familywise alpha.
std::vector<bool> holmRejects(const std::vector<double>& p, double alpha);

}  // namespace dw
