#pragma once
// compare's --heat-map picture of a comparison (and the Python module's
// heat_map=): the FLIP map through Turbo over [0, 1] when FLIP was measured,
// else each pixel's largest channel |difference| over [0, the largest].
#include "renderer/metrics/ImageComparison.h"

namespace dw {

class ComparisonHeatMap {
public:
    static FloatImage of(const ImageComparison& c);
    // The range the picture maps to dark blue .. dark red.
    static double top(const ImageComparison& c);
};

}  // namespace dw
