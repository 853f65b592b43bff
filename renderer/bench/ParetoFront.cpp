#include "renderer/bench/ParetoFront.h"

#include <algorithm>
#include <cmath>

#include "renderer/Error.h"

namespace dw {

ParetoFront::ParetoFront(const std::vector<ParetoPoint>& points) : onFront_(points.size(), false) {
    if (points.empty()) throw Error("no points to compare: the sweep is empty");
    std::vector<size_t> order;
    order.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        // An error of -inf is the best there is (PSNR inf, flipped: the image is identical), so
        // such a point is ranked like any other; NaN and +inf errors are not errors measured.
        if (std::isfinite(points[i].cost) && !std::isnan(points[i].error) && points[i].error != HUGE_VAL)
            order.push_back(i);
    // Left to right: cost ascending, then error, then index (a stable order for duplicates).
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
        if (points[a].error != points[b].error) return points[a].error < points[b].error;
        return a < b;
    });
    // Every point before p costs no more than p. p is on the front when its
    // error is below every earlier error, or it duplicates exactly the front
    // point that holds the lowest error so far (then neither dominates).
    bool any = false;
    double bestError = 0.0, bestCost = 0.0;
    for (size_t i : order) {
        const ParetoPoint& p = points[i];
        if (!any || p.error < bestError) {
            any = true;
            bestError = p.error;
            bestCost = p.cost;
            members_.push_back(i);
        } else if (p.error == bestError && p.cost == bestCost) {
            members_.push_back(i);
        }
    }
    for (size_t i : members_) onFront_[i] = true;
}

}  // namespace dw
