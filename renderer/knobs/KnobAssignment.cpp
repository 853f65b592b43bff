#include "renderer/knobs/KnobAssignment.h"

namespace dw {

KnobAssignment readKnobAssignment(const KnobRegistry& declared, const std::string& knob, const std::string& text) {
    KnobRegistry k = declared;
    k.applyAssignment(knob + "=" + text);
    KnobAssignment a;
    a.knob = declared.canonicalName(knob);
    a.id = *k.find(a.knob);
    a.value = k.value(a.id);
    a.text = k.format(a.id);
    return a;
}

}  // namespace dw
