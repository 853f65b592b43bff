#pragma once
// Light volumes without stencil (seed 000 section 3.2.1): each light's sphere
// or cone drawn with front faces culled, so every pixel behind a back face is
// shaded once, and the shader's in-volume test rejects those outside.
#include "renderer/lighting/LightingStrategy.h"

namespace dw {

class VolumesStrategy : public LightingStrategy {
public:
    explicit VolumesStrategy(KnobRegistry&) {}
    const char* name() const override { return "volumes"; }
    std::string description() const override { return "the volumes' back faces, no stencil test"; }
    StrategyCounts shade(LightingFrame& frame) override;
    // One light: frame.beginLight, then its volume's back faces (also the
    // tiled and clustered strategies' path for lights with a shadow map).
    static void drawVolume(LightingFrame& frame, const LightTableEntry& entry);
};

}  // namespace dw
