#include "renderer/passes/AaMethod.h"

namespace dw {

namespace {

EnumKnob declareKnob(KnobRegistry& knobs) {
    const EnumKnob k = knobs.addEnum(kAaMethodKnob, {"none"}, 0, kAaGroup,
                                     "the anti-aliasing method that makes the display image (docs/antialiasing.md): "
                                     "none: the pixel centres alone",
                                     true);
    const char* note = "anti-aliasing has several methods now, chosen by aa.method";
    knobs.addAlias("fxaa.enabled", kAaMethodKnob, note);
    // fxaa.enabled's values, as its bool parsing took them (any case).
    for (const char* on : {"true", "1", "on", "yes"})
        knobs.addValueAlias(kAaMethodKnob, on, "fxaa", "fxaa.enabled=true is aa.method=fxaa");
    for (const char* off : {"false", "0", "off", "no"})
        knobs.addValueAlias(kAaMethodKnob, off, "none", "fxaa.enabled=false is aa.method=none");
    return k;
}

}  // namespace

EnumKnob declareAaMethod(KnobRegistry& knobs, const std::string& method, const std::string& what, bool isDefault) {
    const std::optional<int> id = knobs.find(kAaMethodKnob);
    const EnumKnob k = id ? knobs.requireEnum(kAaMethodKnob) : declareKnob(knobs);
    knobs.addChoice(k, method, what, isDefault);
    return k;
}

std::string aaMethodSkipReason(const KnobRegistry& knobs, EnumKnob knob, const std::string& method) {
    const std::string picked = knobs.choice(knob);
    if (picked == method) return {};
    return (picked == "none" ? "switched off (aa.method = none)" : "aa.method = " + picked);
}

}  // namespace dw
