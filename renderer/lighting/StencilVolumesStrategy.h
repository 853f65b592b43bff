#pragma once
// Light volumes with the two-pass stencil test of seed 001 section 2.2: the
// first pass marks the pixels whose surface lies inside the volume, the second
// shades only those, through the back faces, zeroing the stencil as it goes
// so no clear is needed between lights. Counting on depth fail (the default)
// stays right with the camera inside a volume; depth pass is the seed's table
// as written. Needs the L-buffer's depth-stencil (lbuffer.depth) bound.
// With lighting.batched_volumes (the default) the lights without a shadow
// map go in batches whose screen rectangles are disjoint
// (renderer/lighting/ScreenBatches.h): per batch one draw marks and
// one shades, so the count per pixel stays exact and the CPU pays two draw
// calls per batch instead of two per light.
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/lighting/LightingStrategy.h"

namespace dw {

class StencilVolumesStrategy : public LightingStrategy {
public:
    enum StencilCount { DepthFail = 0, DepthPass = 1 };
    explicit StencilVolumesStrategy(KnobRegistry& knobs);
    const char* name() const override { return "stencil_volumes"; }
    std::string description() const override {
        return "sphere/cone volumes with the two-pass stencil test (seed 001)";
    }
    StrategyCounts shade(LightingFrame& frame) override;

private:
    EnumKnob stencilCount_;
    BoolKnob batched_;  // lighting.batched_volumes
};

}  // namespace dw
