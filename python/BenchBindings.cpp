// dw.bench: bench's grid (sizes x lights x sweep) in this process, its
// arguments read as bench's flags are, its record returned as a dict.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "python/Arguments.h"
#include "python/Bindings.h"
#include "python/KnobArguments.h"
#include "python/Records.h"
#include "python/Warnings.h"
#include "renderer/OptionLimits.h"

namespace py = pybind11;

namespace dw::python {
namespace {

// sizes: None is bench's default, 160x90; a list of (w, h), at least one (as --sizes).
std::vector<std::pair<int, int>> benchSizes(const py::object& sizesObject) {
    if (sizesObject.is_none()) return {{160, 90}};
    if (!py::isinstance<py::list>(sizesObject) && !py::isinstance<py::tuple>(sizesObject))
        throw py::type_error("bench: sizes must be a list of (width, height), got " + typeName(sizesObject));
    std::vector<std::pair<int, int>> sizes;
    for (const auto& size : sizesObject) sizes.push_back(sizeArg(size, "bench: sizes[]", limits::kSize, "--sizes"));
    if (sizes.empty()) throw py::value_error("bench: sizes is empty (an empty grid measures nothing); None is 160x90");
    return sizes;
}

// lights: None or []: the scene's own lights; else each count once (as --lights).
std::vector<int> benchLights(const py::object& lightsObject) {
    std::vector<int> lights;
    if (lightsObject.is_none()) return lights;
    if (!py::isinstance<py::list>(lightsObject) && !py::isinstance<py::tuple>(lightsObject))
        throw py::type_error("bench: lights must be a list of light counts, got " + typeName(lightsObject));
    for (const auto& n : lightsObject) {
        const int count = intArg(n, "bench: lights[]", limits::kBenchLights, "--lights");
        if (std::find(lights.begin(), lights.end(), count) != lights.end())
            throw py::value_error("bench: lights: " + std::to_string(count) + " is given twice (as --lights)");
        lights.push_back(count);
    }
    return lights;
}

py::object bench(const std::string& scene, const py::object& sizesObject, const py::object& lightsObject,
                 std::optional<py::dict> sweep, py::object preset, std::optional<py::dict> settings,
                 const py::object& framesObject, const py::object& warmupObject, const py::object& blockObject,
                 const py::object& seedObject, std::optional<std::string> csv, std::optional<std::string> json,
                 const std::string& ratioOf, const py::object& resamplesObject, const py::object& orbitObject,
                 bool walkthrough, std::optional<std::string> recordFile, const py::object& sceneTime,
                 const py::object& animation) {
    requirePath(recordFile, "bench: record");
    json = recordPath("bench", json, recordFile);
    BenchOptions o;
    applyRunArguments(o.run, scene, preset, settings);
    applyAnimationArguments(o.run, sceneTime, animation, "bench");
    o.grid.sizes = benchSizes(sizesObject);
    o.grid.lights = benchLights(lightsObject);
    o.grid.knobAxes = sweepAxes("bench", sweep);
    checkKnobs(o.run.sets, o.grid.knobAxes);
    refuseNonSceneFile(o.run.sceneSpec());
    o.frames = intArg(framesObject, "bench: frames", limits::kFrames, "bench --frames");
    o.warmup = intArg(warmupObject, "bench: warmup", limits::kWarmup, "bench --warmup");
    o.block = intArg(blockObject, "bench: block", limits::kBlock, "bench --block");
    o.seed = static_cast<std::uint32_t>(intArg(seedObject, "bench: seed", limits::kSeed, "bench --seed"));
    const int resamples = intArg(resamplesObject, "bench: resamples", limits::kResamples, "bench --resamples");
    // orbit: 0 is a fixed camera, else --orbit's pose count.
    const int orbit = intArg(orbitObject, "bench: orbit", OptionRange{0, limits::kOrbit.max}, "bench --orbit; 0: fixed");
    requirePath(csv, "bench: csv");
    requirePath(json, "bench: json");
    if (orbit > 0 && walkthrough) throw py::value_error("bench: orbit and walkthrough move the camera two ways: give one");
    o.orbit = orbit;
    o.walkthrough = walkthrough;
    BenchResults results;
    ExperimentRecord record;
    {
        py::gil_scoped_release release;
        // bench's warnings (AOV's cost before the frames, issue 22; lost fragments) as RuntimeWarning.
        record = WorkbenchSession::benchRecord(std::move(o), ratioOf, resamples, &results, [](const std::string& line) {
            py::gil_scoped_acquire acquire;
            warnPython(line);
        });
        // Each output on its own, as the CLI writes them: one that fails (a full disk) costs no other.
        std::optional<FileError> failed;
        try {
            if (csv) results.writeCsv(*csv);
        } catch (const FileError& e) {
            failed = e;
        }
        if (json) writeBenchFile(*json, record.json(*json), "bench JSON");
        if (failed) throw *failed;
    }
    return recordObject(record);
}

}  // namespace

void bindBench(py::module_& m) {
    m.def("bench", &bench, py::arg("scene") = "", py::arg("sizes") = py::none(), py::arg("lights") = py::none(),
          py::arg("sweep") = py::none(), py::arg("preset") = py::none(), py::arg("settings") = py::none(),
          py::arg("frames") = 10, py::arg("warmup") = 1, py::arg("block") = 1, py::arg("seed") = 1,
          py::arg("csv") = py::none(), py::arg("json") = py::none(), py::arg("ratio_of") = "frame",
          py::arg("resamples") = 2000, py::arg("orbit") = 0, py::arg("walkthrough") = false, py::arg("record") = py::none(),
          py::arg("scene_time") = py::none(), py::arg("animation") = py::none(),
          "bench's grid (sizes x lights x sweep {knob: [values]}) in this process. Returns the experiment record\n"
          "bench --json writes, as a dict: scene, knobs, seeds, camera path, grid, build, gl, host, and results (configs with\n"
          "their series' statistics, ratios with 95% intervals and every sample); csv=PATH and record=PATH (or json=PATH,\n"
          "its older name) also write bench --csv's and --record's files; orbit=N and walkthrough=True move the camera as bench's options do;\n"
          "scene_time (seconds) and animation (a clip's name or index, or \"none\") as --scene-time and --animation.");
}

}  // namespace dw::python
