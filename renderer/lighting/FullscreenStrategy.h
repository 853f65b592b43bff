#pragma once
// Every light over every pixel (seed 000 section 3.2's naive deferred
// shading): the brute-force reference the volume strategies are measured
// against. The shader's in-volume test keeps the lit region the same.
#include "renderer/lighting/LightingStrategy.h"

namespace dw {

class FullscreenStrategy : public LightingStrategy {
public:
    explicit FullscreenStrategy(KnobRegistry&) {}
    const char* name() const override { return "fullscreen"; }
    std::string description() const override { return "every light over every pixel (the brute-force reference)"; }
    StrategyCounts shade(LightingFrame& frame) override;
};

}  // namespace dw
