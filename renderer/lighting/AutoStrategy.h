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
// scene): volumes win while the lights cover the screen a few times over at
// most (83 lights of radius 1, coverage 1.5: 10.1 ms against tiled's 13.7);
// tiled wins from there (87 lights of radius 2, coverage 6.1: 13.9 against
// 19.1; 893 lights, coverage 56: 37 against 147); clustered wins over tiled
// once the coverage is very high (291 lights of radius 4, coverage 76: 43
// against 49; 2699 of radius 2, coverage 162: 94 against 116), because a
// tile's list holds every light over the tile's whole depth range and a
// cluster's only those of its slice. So:
//   coverage < C   -> stencil_volumes
//   coverage >= K  -> clustered
//   otherwise      -> tiled
// C and K the knobs lighting.auto_coverage and lighting.auto_cluster_coverage.
// The mean light's share of the screen (coverage / lights) did not decide
// anything the coverage did not, so it is reported but not used. Depth
// complexity (how many surfaces stack per pixel) is not an input: the
// G-buffer keeps one surface per pixel, so it changes none of these
// strategies' lighting cost; the depth range a tile spans is what separates
// tiled from clustered, and the coverage grows with it.
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
