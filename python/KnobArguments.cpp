#include "python/KnobArguments.h"

#include "python/Arguments.h"
#include "python/WorkbenchSession.h"
#include "renderer/RunConfig.h"
#include "renderer/bench/TradeoffSweep.h"

namespace py = pybind11;

namespace dw::python {

py::object knobValue(const KnobRegistry& knobs, int id) {
    const KnobSpec& s = knobs.spec(id);
    const double v = knobs.value(id);
    switch (s.type) {
        case KnobType::Bool: return py::bool_(v != 0.0);
        case KnobType::Int: return py::int_(static_cast<long long>(v));
        case KnobType::Float: return py::float_(v);
        case KnobType::Enum: return py::str(s.choices[static_cast<size_t>(v)]);
    }
    return py::none();
}

std::string knobText(const py::handle& value) {
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) return py::str(value).cast<std::string>();
    // numpy scalars and the like: their str() is what --set would take
    return py::str(value).cast<std::string>();
}

std::vector<std::string> presetList(const py::object& preset) {
    if (preset.is_none()) return {};
    if (py::isinstance<py::str>(preset)) return {preset.cast<std::string>()};
    if (py::isinstance<py::list>(preset) || py::isinstance<py::tuple>(preset)) {
        std::vector<std::string> out;
        for (const auto& item : preset) {
            if (!py::isinstance<py::str>(item)) throw py::value_error("preset: a list holds presets' names or files (str)");
            out.push_back(item.cast<std::string>());
        }
        return out;
    }
    throw py::value_error("preset: a preset's name or file, or a list of them");
}

std::vector<std::string> assignments(const std::optional<py::dict>& settings) {
    std::vector<std::string> sets;
    if (settings)
        for (const auto& [k, v] : *settings) sets.push_back(py::str(k).cast<std::string>() + "=" + knobText(v));
    return sets;
}

void applyRunArguments(RunConfig& run, const std::string& scene, const py::object& preset,
                       const std::optional<py::dict>& settings) {
    run.scene = scene;
    for (const auto& p : presetList(preset)) run.addPreset(p);
    run.sets = assignments(settings);
}

void applyAnimationArguments(RunConfig& run, const py::object& sceneTime, const py::object& animation,
                             const std::string& command) {
    if (!sceneTime.is_none())
        run.sceneTime = numberArg(sceneTime, command + ": scene_time", limits::kSceneTime, command + " --scene-time");
    if (!animation.is_none()) run.animation = py::str(animation).cast<std::string>();
}

std::vector<BenchKnobAxis> sweepAxes(const std::string& command, const std::optional<py::dict>& sweep) {
    std::vector<BenchKnobAxis> axes;
    if (!sweep) return axes;
    for (const auto& [k, values] : *sweep) {
        BenchKnobAxis axis;
        axis.knob = py::str(k).cast<std::string>();
        if (py::isinstance<py::str>(values) || !py::isinstance<py::sequence>(values))
            throw py::value_error(command + ": sweep['" + axis.knob + "'] must be a list of values, got " + typeName(values));
        for (const auto& v : values) axis.values.push_back(knobText(v));
        if (axis.values.empty())
            throw py::value_error(command + ": sweep['" + axis.knob + "'] has no values (an empty axis leaves no configuration)");
        axes.push_back(axis);
    }
    return axes;
}

void checkKnobs(const std::vector<std::string>& sets, const std::vector<BenchKnobAxis>& axes) {
    KnobRegistry declared = RunConfig::declaredKnobs();
    try {
        for (const std::string& a : sets) declared.applyAssignment(a);
        for (const BenchKnobAxis& axis : axes) {
            if (axis.knob == "preset" || TradeoffSweep::isCameraAxis(axis.knob)) continue;
            for (const std::string& v : axis.values) declared.setFromString(axis.knob, v);
        }
    } catch (const Error& e) {
        throw KnobError(e.what());
    }
}

}  // namespace dw::python
