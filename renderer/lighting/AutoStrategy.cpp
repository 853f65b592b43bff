#include "renderer/lighting/AutoStrategy.h"

#include <cstdio>

namespace dw {

AutoStrategyChoice chooseLightingStrategy(const AutoStrategyInputs& in, const AutoStrategyThresholds& at) {
    if (in.lights <= 0) return {"stencil_volumes", "no bounded lights in view"};
    const bool grid = in.coverage >= at.coverage, clusters = in.coverage >= at.clusterCoverage;
    const char* picked = clusters ? "clustered" : grid ? "tiled" : "stencil_volumes";
    char line[240];
    std::snprintf(line, sizeof(line), "%d lights in view, screen coverage %.2f (%s %.2f, %s %.2f), %.4f of the screen each",
                  in.lights, in.coverage, grid ? ">=" : "<", at.coverage, clusters ? ">=" : "<", at.clusterCoverage,
                  in.coverage / in.lights);
    return {picked, line};
}

}  // namespace dw
