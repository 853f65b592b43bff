#pragma once
// lighting.strategy = auto: per frame, the lighting pass picks a strategy from
// what the frame holds (issue: "auto picks from light count, screen
// coverage ..."): the bounded lights in view, and their screen coverage, the
// sum over those lights of the screen rectangle their volume can cover
// (ScreenBatches.h's screenRect) as a fraction of the image: about how many
// times the stencil strategy rasterises each pixel.
//
// Light volumes (stencil_volumes) pay for every pixel each volume covers
// (marked, and shaded where a surface is inside) plus two draws per batch;
// the grid strategies pay a fixed cost per pixel (depth bounds, a walk over
// every pixel) plus the lists they walk, which grow with the coverage.
// Measured (docs/bench.md, "auto"; lighting pass at 640x360 in the default
// scene on llvmpipe): volumes win while the lights cover the screen up to
// about 9 times over (131 lights of radius 2, coverage 8.35: 13.3 ms against
// tiled's 14.4; at 7.75 the two were even, 15.6 against 14.7); tiled wins
// from there (595 lights of radius 1, coverage 10.9: 14.7 against 19.1; 893
// lights of radius 2, coverage 56: 23.6 against 59.1).
// A cluster's list holds only the lights of its depth slice, a tile's every
// light across the tile's depth range, so with enough lights clustered
// could overtake tiled; on llvmpipe it did not, up to coverage 657 (2923
// lights of radius 4: 215 against 256 ms). So:
//   coverage < C   -> stencil_volumes
//   coverage >= K  -> clustered
//   otherwise      -> tiled
// C and K the knobs lighting.auto_coverage (9) and
// lighting.auto_cluster_coverage (1e6 by default: never, on this evidence;
// a machine where clustered wins sets it from its own bench run). The mean
// light's share of the screen (coverage / lights) is reported, not used.
// Depth complexity (how many surfaces stack per pixel) is not an input: the
// G-buffer keeps one surface per pixel, so it changes none of these
// strategies' lighting cost; what a tile's depth range spans is what
// separates tiled from clustered, and the coverage grows with it.
#include <string>

namespace dw {

struct AutoStrategyInputs {
    int lights = 0;         // bounded (point and spot) lights inside the view frustum
    double coverage = 0.0;  // sum of their screen rectangles' areas / the image's area
};

struct AutoStrategyThresholds {
    double coverage = 0.0;         // C: screens covered, summed over the lights, from which tiled
    double clusterCoverage = 0.0;  // K: and from which clustered
};

struct AutoStrategyChoice {
    const char* strategy;  // a lighting.strategy value
    std::string why;       // one line for the pass statistics
};

AutoStrategyChoice chooseLightingStrategy(const AutoStrategyInputs& in, const AutoStrategyThresholds& at);

}  // namespace dw
