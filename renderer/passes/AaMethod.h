#pragma once
// aa.method (issue 35): which anti-aliasing method makes the display image,
// one knob whose choices are the anti-aliasing passes that exist. Each such
// pass (FxaaPass, SsaaPass, TaaPass: a pass file pair and one line in
// BuiltinPasses.cpp) adds its name with declareAaMethod in its constructor;
// the first call declares the knob with the choice `none` and the old name
// fxaa.enabled (true stands for aa.method=fxaa, false for none, with a
// warning, as ssao.enabled stands for ao.enabled). docs/antialiasing.md.
#include <string>

#include "renderer/knobs/KnobRegistry.h"

namespace dw {

inline constexpr const char* kAaMethodKnob = "aa.method";
// The group (KnobSpec::pass) of aa.method and of the methods' own aa.* knobs:
// the anti-aliasing passes together, one group in the Knobs panel.
inline constexpr const char* kAaGroup = "aa";

// Adds `method` (with one sentence of what it does) to aa.method, declaring
// the knob first if no pass did yet; `isDefault` makes it the default.
EnumKnob declareAaMethod(KnobRegistry& knobs, const std::string& method, const std::string& what,
                         bool isDefault = false);

// Empty when aa.method names `method`; otherwise the skip reason the inspector
// shows ("aa.method = ssaa").
std::string aaMethodSkipReason(const KnobRegistry& knobs, EnumKnob knob, const std::string& method);

}  // namespace dw
