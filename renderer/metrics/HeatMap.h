#pragma once
// Error maps as pictures: a one-channel map through Google's Turbo colour map
// (shaders/bufferview/turbo.h, the same polynomial the buffer view's heat map
// and the workbench's colour bar use), `low` -> dark blue, `high` -> dark red,
// values outside clamped. The result is RGB display values in [0, 1] (what an
// 8-bit PNG stores).
#include "renderer/io/ImageIO.h"

namespace dw {

class HeatMap {
public:
    // `map` width x height x channels; `channel` the one shown. Throws Error
    // when `channel` is out of range or high <= low.
    static FloatImage colour(const FloatImage& map, int channel, double low, double high);
};

}  // namespace dw
