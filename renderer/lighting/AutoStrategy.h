#pragma once
// lighting.strategy = auto: per frame, the lighting pass picks a strategy from
// what the frame holds (issue: "auto picks from light count, screen
// coverage ..."): the bounded lights in view, and their screen coverage, the
// sum over those lights of the screen rectangle their volume can cover
// (ScreenBatches.h's screenRect) as a fraction of the image: about how many
// times the stencil strategy rasterises each pixel.
//
// Light volumes (stencil_volumes) pay for every pixel each volume covers
// (marked, and shaded where a surface is inside); the clustered grid pays a
// fixed cost per pixel (the cluster build and a full-screen pass) plus the
// lists it walks, about proportional to the coverage whatever the lights'
// size. Measured (docs/bench.md, "auto"), the grid wins when the lights cover
// the screen many times over AND each light is large on screen: many small
// lights (radius 1 in the default scene, 2587 in view covering it 43 times,
// 1.3% of the screen each) still favour volumes, 96 large ones (23 times,
// 24% each) favour the grid 1.5x. So: clustered when coverage >= C and
// coverage / lights >= S, stencil_volumes otherwise, C and S the knobs
// lighting.auto_coverage and lighting.auto_light_size. Depth complexity (how
// many surfaces stack per pixel) is not an input yet.
#include <string>

namespace dw {

struct AutoStrategyInputs {
    int lights = 0;         // bounded (point and spot) lights inside the view frustum
    double coverage = 0.0;  // sum of their screen rectangles' areas / the image's area
};

struct AutoStrategyThresholds {
    double coverage = 0.0;   // C: screens covered, summed over the lights
    double lightSize = 0.0;  // S: the mean light's screen rectangle, as a fraction of the screen
};

struct AutoStrategyChoice {
    const char* strategy;  // a lighting.strategy value
    std::string why;       // one line for the pass statistics
};

AutoStrategyChoice chooseLightingStrategy(const AutoStrategyInputs& in, const AutoStrategyThresholds& at);

}  // namespace dw
