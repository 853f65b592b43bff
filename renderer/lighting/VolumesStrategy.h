#pragma once
// Light volumes without stencil (seed 000 section 3.2.1): each light's sphere
// or cone drawn with front faces culled, so every pixel behind a back face is
// shaded once, and the shader's in-volume test rejects those outside.
// With lighting.batched_volumes (the default) every light without a shadow
// map is drawn in one call (LightShading::uploadVolumeBatch; blending is
// additive, so the lights need no order); lights with a shadow map go one at
// a time, after their map.
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/lighting/LightingStrategy.h"

namespace dw {

// lighting.batched_volumes, declared by whichever volume strategy asks first.
BoolKnob declareBatchedVolumesKnob(KnobRegistry& knobs);

class VolumesStrategy : public LightingStrategy {
public:
    explicit VolumesStrategy(KnobRegistry& knobs) : batched_(declareBatchedVolumesKnob(knobs)) {}
    const char* name() const override { return "volumes"; }
    std::string description() const override { return "the volumes' back faces, no stencil test"; }
    StrategyCounts shade(LightingFrame& frame) override;
    // One light: frame.beginLight, then its volume's back faces (also the
    // tiled and clustered strategies' path for lights with a shadow map).
    static void drawVolume(LightingFrame& frame, const LightTableEntry& entry);

private:
    BoolKnob batched_;
};

}  // namespace dw
