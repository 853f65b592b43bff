#pragma once
// The Pareto front of points that each cost something and miss by something:
// the points no other point beats on both at once. `tradeoff` marks its
// front with it (cost = a configuration's median GPU frame milliseconds,
// miss = its error against the reference, both minimised).
//
// Exact, on the numbers as given (no tolerance):
//   q dominates p  <=>  q.cost <= p.cost and q.error <= p.error, and q is
//   strictly lower on at least one of the two.
// So of two points with the same cost the one with the larger error is off
// the front; exact duplicates dominate neither the other and are both on it;
// a single point is its own front. An error of -inf is the lowest error
// there is (a PSNR of inf, flipped: an image identical to the one measured
// against) and ranks as such. A point whose cost is not a finite number, or
// whose error is NaN or +inf, is never on the front and dominates nothing.
// Needs no GL.
#include <cstddef>
#include <vector>

namespace dw {

struct ParetoPoint {
    double cost = 0.0;   // minimised (milliseconds)
    double error = 0.0;  // minimised (flip on a larger-is-better metric before)
};

class ParetoFront {
public:
    // Throws dw::Error when `points` is empty ("no points to compare: the
    // sweep is empty"). Points whose coordinates are all non-finite give an
    // empty front, not an error.
    explicit ParetoFront(const std::vector<ParetoPoint>& points);

    // The indices (into the points given) on the front, by cost ascending,
    // then error, then index: the front read from left to right.
    const std::vector<size_t>& members() const { return members_; }
    bool contains(size_t index) const { return index < onFront_.size() && onFront_[index]; }
    size_t size() const { return members_.size(); }

private:
    std::vector<size_t> members_;
    std::vector<bool> onFront_;
};

}  // namespace dw
