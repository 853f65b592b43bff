#include "renderer/lighting/AutoStrategy.h"

#include <cstdio>

namespace dw {

AutoStrategyChoice chooseLightingStrategy(const AutoStrategyInputs& in, const AutoStrategyThresholds& at) {
    if (in.lights <= 0) return {"stencil_volumes", "no bounded lights in view"};
    char line[200];
    const double size = in.lights > 0 ? in.coverage / in.lights : 0.0;
    const bool covering = in.coverage >= at.coverage, large = in.lights > 0 && size >= at.lightSize;
    std::snprintf(line, sizeof(line), "%d lights in view, screen coverage %.2f (%s %.2f), %.4f of the screen each (%s %.4f)",
                  in.lights, in.coverage, covering ? ">=" : "<", at.coverage, size, large ? ">=" : "<", at.lightSize);
    return {covering && large ? "clustered" : "stencil_volumes", line};
}

}  // namespace dw
