#pragma once
// Knobs, presets and sweeps between Python and the registry: values as
// Python objects, Python values as --set writes them, and the run
// configuration's arguments (preset=, settings=, sweep=) of Session, bench
// and tradeoff, read as their CLI flags are.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "renderer/RunConfig.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/knobs/KnobRegistry.h"

namespace dw::python {

// Knob `id`'s value: bool, int, float, or the enum's choice as a str.
pybind11::object knobValue(const KnobRegistry& knobs, int id);

// A Python value as --set writes it: True -> "true", 16 -> "16", 0.02 -> "0.02".
std::string knobText(const pybind11::handle& value);

// preset=: None, a preset's name or file, or a list of them (applied in
// order, as repeated --preset). Anything else is ValueError.
std::vector<std::string> presetList(const pybind11::object& preset);

// {knob: value} as --set assignments.
std::vector<std::string> assignments(const std::optional<pybind11::dict>& settings);

// bench's and tradeoff's scene=, preset= and settings= into `run`, as
// --scene, --preset and --set give them (its other fields are left as they are).
// scene_time= and animation= (render/bench/tradeoff's --scene-time and
// --animation): held to --scene-time's range; None leaves the default.
void applyAnimationArguments(RunConfig& run, const pybind11::object& sceneTime, const pybind11::object& animation,
                             const std::string& command);
void applyRunArguments(RunConfig& run, const std::string& scene, const pybind11::object& preset,
                       const std::optional<pybind11::dict>& settings);

// A sweep {knob: [values]} as bench's and tradeoff's axes, each value as
// --sweep writes it; `command` names the function in the messages. As the
// CLI's --sweep: a list of values, at least one (an empty axis is an empty
// grid); ValueError otherwise.
std::vector<BenchKnobAxis> sweepAxes(const std::string& command, const std::optional<pybind11::dict>& sweep);

// Knob names and values with the registry's checks first (KnobError), as
// Session does: the settings, and each axis that is a knob (tradeoff's
// preset and clip-plane axes are checked by its runner).
void checkKnobs(const std::vector<std::string>& sets, const std::vector<BenchKnobAxis>& axes);

}  // namespace dw::python
