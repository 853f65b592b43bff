#pragma once
// What `--set knob=text` would set, read once and carried typed: the sweeps
// of `bench` and `tradeoff` read each axis value through it when they check
// it, write its text to the CSV and apply its value, so no later step parses
// the text again. Needs no GL.
#include <string>

#include "renderer/knobs/KnobRegistry.h"

namespace dw {

struct KnobAssignment {
    std::string knob;   // the knob's name (an old name read as the knob it became, with --set's warning)
    int id = -1;        // the knob's id in the registry it was read against (KnobRegistry::find)
    double value = 0.0; // as KnobRegistry::set takes it: an enum's choice number, a bool 0 or 1
    std::string text;   // the value as the knob writes it (a float's shortest text, which reads back exactly)
};

// Throws dw::Error as KnobRegistry::applyAssignment does (an unknown knob, a
// value the knob does not take), without changing `declared`.
KnobAssignment readKnobAssignment(const KnobRegistry& declared, const std::string& knob, const std::string& text);

}  // namespace dw
