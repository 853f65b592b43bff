// The Python module deferred_workbench (pybind11): Session over
// WorkbenchSession, images as numpy arrays (H x W x C, top row first; uint8
// for 8-bit display outputs, float32 for everything else), records as dicts.
// This file only converts types and holds the GIL rules: the GIL is released
// while frames render, shaders compile and the CPU reference traces.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <future>
#include <limits>
#include <thread>
#include <tuple>

#include "headless/CommandLine.h"
#include "headless/PlotScript.h"
#include "python/ModuleInit.h"
#include "python/WorkbenchSession.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/OptionLimits.h"
#include "renderer/bench/TradeoffStudy.h"
#include "renderer/io/TextFile.h"
#include "renderer/metrics/ImageComparison.h"
#include "renderer/metrics/ComparisonHeatMap.h"
#include "renderer/metrics/ComparisonMemory.h"

namespace py = pybind11;

namespace dw {
namespace {

// A warning as Python reports one (warnings.warn, RuntimeWarning); with the
// warnings filter set to "error" it is raised. Needs the GIL.
void warnPython(const std::string& line) {
    if (PyErr_WarnEx(PyExc_RuntimeWarning, line.c_str(), 1) != 0) throw py::error_already_set();
}

std::string typeName(const py::handle& value) {
    return py::str(py::type::of(value).attr("__name__")).cast<std::string>();
}

// An integer argument held to `range`, the range of the CLI option it stands
// for (renderer/OptionLimits.h; `flag` names that option). A Python int of
// any size or what has __index__ (numpy's integers) is range-checked before
// it is narrowed: outside the range, however large, is ValueError naming the
// argument and the range. None, bool, float, str and the rest are TypeError.
int intArg(const py::handle& value, const std::string& name, OptionRange range, const std::string& flag = {}) {
    const std::string expected = name + " must be an integer between " + std::to_string(range.min) + " and " +
                                 std::to_string(range.max) + (flag.empty() ? "" : " (as " + flag + ")");
    if (value.is_none() || PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
        throw py::type_error(expected + ", got " + typeName(value));
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
    if (!index) throw py::error_already_set();
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow == 0 && v == -1 && PyErr_Occurred()) throw py::error_already_set();
    if (overflow != 0) throw py::value_error(expected + ", got an integer beyond 64 bits");
    if (!range.holds(v)) throw py::value_error(expected + ", got " + std::to_string(v));
    return static_cast<int>(v);
}

// A finite number (int or float, not bool) in `range`, the range of the CLI
// option it stands for (renderer/OptionLimits.h; `flag` names it): ValueError
// naming the argument when it is NaN, infinite, too large for a double or
// outside the range; TypeError for anything that is not a number.
double numberArg(const py::handle& value, const std::string& name, RealRange range, const std::string& flag) {
    char bound[96];
    std::snprintf(bound, sizeof bound, range.minOpen ? "above %g and at most %g" : "from %g to %g", range.min, range.max);
    const std::string expected = name + " must be a finite number " + bound + " (as " + flag + ")";
    if (value.is_none() || PyBool_Check(value.ptr()) || PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr()))
        throw py::type_error(expected + ", got " + typeName(value));
    const double v = PyFloat_AsDouble(value.ptr());
    if (v == -1.0 && PyErr_Occurred()) {
        const bool overflow = PyErr_ExceptionMatches(PyExc_OverflowError) != 0;
        PyErr_Clear();
        if (overflow) throw py::value_error(expected + ", got a number beyond a double's range");
        throw py::type_error(expected + ", got " + typeName(value));
    }
    if (!range.holds(v)) throw py::value_error(expected + ", got " + py::repr(value).cast<std::string>());
    return v;
}

// (width, height): a tuple or list of two integers, each in `range` (--size's).
std::pair<int, int> sizeArg(const py::handle& value, const std::string& name, OptionRange range = limits::kSize,
                            const std::string& flag = {}) {
    if (!(py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) || py::len(value) != 2)
        throw py::type_error(name + " must be (width, height), two integers, got " +
                             (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)
                                  ? std::to_string(py::len(value)) + " items"
                                  : typeName(value)));
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(value);
    return {intArg(py::object(pair[0]), name + " width", range, flag), intArg(py::object(pair[1]), name + " height", range, flag)};
}

// A file argument: an empty path names no file (ValueError naming the argument).
void requirePath(const std::optional<std::string>& path, const std::string& name) {
    if (path && path->empty()) throw py::value_error(name + " is an empty path: name a file");
}

// A callable or None (progress=).
void requireCallable(const py::object& f, const std::string& name) {
    if (!f.is_none() && !PyCallable_Check(f.ptr()))
        throw py::type_error(name + " must be a callable or None, got " + typeName(f));
}

// The CPU reference's options (reference's --ao-rays, --seed, --threads, --no-cache, --cache-dir).
ReferenceOptions referenceOptions(const std::string& function, const py::handle& aoRays, const py::handle& seed,
                                  const py::handle& threads, bool cache, const std::optional<std::string>& cacheDir) {
    ReferenceOptions o;
    o.aoRays = intArg(aoRays, function + ": ao_rays", limits::kAoRays, "reference --ao-rays");
    o.seed = intArg(seed, function + ": seed", limits::kSeed, "reference --seed");
    o.threads = intArg(threads, function + ": threads", limits::kReferenceThreads, "reference --threads; 0: every core");
    o.useCache = cache;
    o.cacheDirectory = cacheDir.value_or("");
    return o;
}

// Traces the CPU reference (`trace`, CPU only) on a worker thread while this
// one waits with the GIL released; every 0.2 s it takes the GIL to see
// Ctrl-C and to call progress(fraction done). KeyboardInterrupt, or what
// progress raised, cancels the trace and is raised; progress(1.0) last.
reference::ReferenceImages traceReference(const py::object& progressFn,
                                          const std::function<reference::ReferenceImages(reference::ReferenceProgress*)>& trace) {
    reference::ReferenceProgress progress;
    reference::ReferenceImages images;
    std::exception_ptr failure;
    bool raised = false;
    {
        py::gil_scoped_release release;
        std::promise<void> finished;
        std::future<void> done = finished.get_future();
        std::thread worker([&] {
            try {
                images = trace(&progress);
            } catch (...) {
                failure = std::current_exception();
            }
            finished.set_value();
        });
        while (done.wait_for(std::chrono::milliseconds(200)) != std::future_status::ready) {
            py::gil_scoped_acquire acquire;
            if (raised) continue;
            if (PyErr_CheckSignals() != 0) {
                raised = true;
            } else if (!progressFn.is_none()) {
                try {
                    progressFn(progress.fraction());
                } catch (py::error_already_set& e) {
                    e.restore();
                    raised = true;
                }
            }
            if (raised) progress.cancel.store(true);
        }
        worker.join();
    }
    if (raised) throw py::error_already_set();
    if (failure) std::rethrow_exception(failure);
    if (!progressFn.is_none()) progressFn(1.0);
    return images;
}

py::array toArray(const BufferImage& image) {
    const std::vector<py::ssize_t> shape = {image.height, image.width, image.channels};
    if (image.eightBit) {
        py::array_t<std::uint8_t> a(shape);
        std::memcpy(a.mutable_data(), image.bytes.data(), image.bytes.size());
        return a;
    }
    py::array_t<float> a(shape);
    std::memcpy(a.mutable_data(), image.floats.data(), image.floats.size() * sizeof(float));
    return a;
}

py::array_t<float> toArray(const FloatImage& image) {
    py::array_t<float> a(std::vector<py::ssize_t>{image.height, image.width, image.channels});
    std::memcpy(a.mutable_data(), image.pixels.data(), image.pixels.size() * sizeof(float));
    return a;
}

// An H x W (x C) array as a FloatImage: uint8 as display values v / 255,
// anything else as float32.
FloatImage toFloatImage(const py::array& input, const char* what) {
    if (input.ndim() != 2 && input.ndim() != 3)
        throw Error(std::string(what) + ": expected an H x W or H x W x C array, got " + std::to_string(input.ndim()) +
                    " dimensions");
    // Every side at least 1 (an image without pixels or channels has no error to measure), each within an int.
    for (py::ssize_t d = 0; d < input.ndim(); ++d)
        if (input.shape(d) < 1 || input.shape(d) > std::numeric_limits<int>::max())
            throw py::value_error(std::string(what) + ": an H x W (x C) array with every side from 1 to " +
                                  std::to_string(std::numeric_limits<int>::max()) + ", got " +
                                  py::str(py::tuple(input.attr("shape"))).cast<std::string>());
    FloatImage image;
    image.height = static_cast<int>(input.shape(0));
    image.width = static_cast<int>(input.shape(1));
    image.channels = input.ndim() == 3 ? static_cast<int>(input.shape(2)) : 1;
    image.pixels.resize(static_cast<size_t>(input.size()));
    if (py::isinstance<py::array_t<std::uint8_t>>(input)) {
        auto bytes = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(input);
        for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<float>(bytes.data()[i]) / 255.0f;
    } else {
        auto floats = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(input);
        if (!floats) throw Error(std::string(what) + ": not convertible to float32");
        std::memcpy(image.pixels.data(), floats.data(), image.pixels.size() * sizeof(float));
    }
    return image;
}

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

// A Python value as --set writes it: True -> "true", 16 -> "16", 0.02 -> "0.02".
std::string knobText(const py::handle& value) {
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) return py::str(value).cast<std::string>();
    // numpy scalars and the like: their str() is what --set would take
    return py::str(value).cast<std::string>();
}

// A record as Python objects: the JSON it writes, read by Python's json module.
py::object recordObject(const ExperimentRecord& record) {
    return py::module_::import("json").attr("loads")(record.json());
}

// record=PATH and json=PATH are one keyword of bench and tradeoff (the CLI's
// --record FILE and its older name --json FILE): the experiment record.
std::optional<std::string> recordPath(const std::string& function, std::optional<std::string> json,
                                      std::optional<std::string> record) {
    if (json && record && *json != *record)
        throw py::value_error(function + ": record='" + *record + "' and json='" + *json +
                              "' name two files: give one (json= is record='s older name)");
    return record ? record : json;
}

// A dict of plain values as indented JSON (Python's json module), whole or not at all.
void writeJsonObject(const std::string& path, const py::dict& d) {
    const std::string text = py::module_::import("json").attr("dumps")(d, py::arg("indent") = 2).cast<std::string>() + "\n";
    py::gil_scoped_release release;
    writeFileAtomically(path, text);
}

py::dict statsDict(const TimingStats& s) {
    py::dict d;
    d["count"] = s.count;
    d["median"] = s.median;
    d["mean"] = s.mean;
    d["min"] = s.min;
    d["max"] = s.max;
    return d;
}

py::list timingList(const TimingReport& report) {
    py::list rows;
    for (const TimingRow& r : report.rows()) {
        py::dict d;
        d["name"] = r.series;
        d["kind"] = r.kind == TimingRow::Kind::Pass ? "pass" : r.kind == TimingRow::Kind::Span ? "span" : "total";
        d["pass"] = r.pass;
        d["ran"] = r.ran;
        d["reason"] = r.reason;
        d["stats"] = r.stats;
        d["gpu_ms"] = statsDict(r.gpu);
        d["cpu_ms"] = statsDict(r.cpu);
        rows.append(d);
    }
    return rows;
}

py::tuple vec(const glm::vec3& v) { return py::make_tuple(v.x, v.y, v.z); }
py::tuple vec(const glm::vec4& v) { return py::make_tuple(v.x, v.y, v.z, v.w); }

py::dict probeDict(const ProbeResult& p) {
    py::dict d;
    d["x"] = p.x;
    d["y"] = p.y;
    d["inside"] = p.inside;
    const SurfaceSample& s = p.surface;
    py::dict surface;
    surface["background"] = s.background;
    surface["depth"] = s.depth;
    surface["linear_depth"] = s.linearDepth;
    surface["view_position"] = vec(s.viewPosition);
    surface["world_position"] = vec(s.worldPosition);
    surface["view_normal"] = vec(s.viewNormal);
    surface["albedo"] = vec(s.albedo);
    surface["specular"] = vec(s.specular);
    surface["emissive"] = vec(s.emissive);
    surface["exponent"] = s.exponent;
    surface["radiance"] = vec(s.radiance);
    surface["luminance"] = s.luminance;
    d["surface"] = surface;
    py::dict values;
    for (const ProbeValue& v : p.values) {
        py::dict e;
        e["kind"] = toString(v.kind);
        e["channels"] = v.channels;
        e["raw"] = vec(v.raw);
        if (!v.samples.empty()) {
            py::list samples;
            for (const auto& x : v.samples) samples.append(vec(x));
            e["samples"] = samples;
        }
        if (!v.words.empty()) e["words"] = v.words;
        values[py::str(v.output)] = e;
    }
    d["values"] = values;
    return d;
}

py::dict figuresDict(const DifferenceFigures& f) {
    py::dict d;
    d["mean"] = f.mean;
    d["rms"] = f.rms;
    d["psnr"] = f.psnr;
    d["max"] = f.max;
    d["max_pixel"] = py::make_tuple(f.maxX, f.maxY);
    d["max_channel"] = f.maxChannel;
    d["warn_count"] = f.warnCount;
    d["fail_count"] = f.failCount;
    return d;
}

py::dict referenceStats(const reference::ReferenceStatistics& s) {
    py::dict d;
    d["seconds"] = s.seconds;
    d["build_seconds"] = s.buildSeconds;
    d["threads"] = s.threads;
    d["primary_rays"] = s.primaryRays;
    d["shadow_rays"] = s.shadowRays;
    d["ao_rays"] = s.aoRays;
    d["blended_hits"] = s.blendedHits;
    d["ao_standard_error_mean"] = s.aoStandardErrorMean;
    d["ao_standard_error_max"] = s.aoStandardErrorMax;
    d["triangles"] = s.triangles;
    return d;
}

py::dict compareArrays(const py::array& reference, const py::array& test, bool hdr, const py::object& warnObject,
                       const py::object& failObject, bool maps, std::optional<std::string> errorMap,
                       std::optional<std::string> heatMap, std::optional<std::string> json) {
    // compare's --warn and --fail: finite, at least 0.
    requirePath(errorMap, "compare: error_map");
    requirePath(heatMap, "compare: heat_map");
    requirePath(json, "compare: json");
    const double warnThreshold = numberArg(warnObject, "compare: warn_threshold", limits::kThreshold, "compare --warn");
    const double failThreshold = numberArg(failObject, "compare: fail_threshold", limits::kThreshold, "compare --fail");
    if (errorMap && !isFloatFormat(*errorMap))
        throw Error("error_map writes float maps: give it an .exr name, got '" + *errorMap + "'");
    // The image memory budget (DW_IMAGE_LIMIT_MB) before a pixel is copied, as compare on files.
    for (const auto& [array, what] : {std::pair{&reference, "reference"}, std::pair{&test, "test"}})
        if (array->ndim() >= 2)
            if (const std::string why = comparison_memory::refusal(
                    static_cast<int>(std::min<py::ssize_t>(array->shape(1), std::numeric_limits<int>::max())),
                    static_cast<int>(std::min<py::ssize_t>(array->shape(0), std::numeric_limits<int>::max())),
                    array->ndim() == 3 ? static_cast<int>(std::min<py::ssize_t>(array->shape(2), 1 << 20)) : 1);
                !why.empty())
                throw Error(std::string("compare: ") + what + " is " + why);
    const FloatImage a = toFloatImage(reference, "reference");
    const FloatImage b = toFloatImage(test, "test");
    ComparisonSettings settings;
    settings.hdr = hdr;
    // HDR-FLIP's exposures at once: as many as the budget holds (the result is the same).
    settings.flip.maxThreads = comparison_memory::flipThreadsWithin(a.width, a.height, a.channels);
    settings.warnThreshold = warnThreshold;
    settings.failThreshold = failThreshold;
    ImageComparison c;
    {
        py::gil_scoped_release release;
        c = ImageComparison::measure(a, b, settings);
    }
    py::dict d = figuresDict(c.difference.overall);
    d["hdr"] = c.hdr;
    d["pixel_count"] = c.difference.pixelCount;
    py::list perChannel;
    for (const auto& f : c.difference.perChannel) perChannel.append(figuresDict(f));
    d["per_channel"] = perChannel;
    d["ssim"] = c.ssim ? py::object(py::float_(c.ssim->mean)) : py::object(py::none());
    d["flip"] = c.flip ? py::object(py::float_(c.flip->mean)) : py::object(py::none());
    d["notes"] = c.notes;
    {
        py::gil_scoped_release release;
        if (errorMap) {
            std::vector<std::string> names;
            const FloatImage map = c.errorMap(names);
            writeImage(*errorMap, map, names);
        }
        if (heatMap) writeImage(*heatMap, ComparisonHeatMap::of(c));
    }
    if (json) writeJsonObject(*json, d);
    if (maps) {
        py::dict m;
        m["difference"] = toArray(c.absoluteDifference);
        if (c.ssim) m["ssim"] = toArray(c.ssim->map);
        if (c.flip) m["flip"] = toArray(c.flip->map);
        d["maps"] = m;
    }
    return d;
}

// A sweep {knob: [values]} as bench's and tradeoff's axes, each value as
// --sweep writes it; `command` names the function in the messages. As the
// CLI's --sweep: a list of values, at least one (an empty axis is an empty grid).
std::vector<BenchKnobAxis> sweepAxes(const std::string& command, const std::optional<py::dict>& sweep) {
    std::vector<BenchKnobAxis> axes;
    if (!sweep) return axes;
    for (const auto& [k, values] : *sweep) {
        BenchKnobAxis axis;
        axis.knob = py::str(k).cast<std::string>();
        if (py::isinstance<py::str>(values) || !py::isinstance<py::sequence>(values))
            throw py::value_error(command + ": sweep['" + axis.knob + "'] must be a list of values, got " +
                                  py::str(py::type::of(values).attr("__name__")).cast<std::string>());
        for (const auto& v : values) axis.values.push_back(knobText(v));
        if (axis.values.empty())
            throw py::value_error(command + ": sweep['" + axis.knob + "'] has no values (an empty axis leaves no configuration)");
        axes.push_back(axis);
    }
    return axes;
}

// preset=: None, a preset's name or file, or a list of them (applied in
// order, as repeated --preset). Anything else is ValueError.
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

// {knob: value} as --set assignments.
std::vector<std::string> assignments(const std::optional<py::dict>& settings) {
    std::vector<std::string> sets;
    if (settings)
        for (const auto& [k, v] : *settings) sets.push_back(py::str(k).cast<std::string>() + "=" + knobText(v));
    return sets;
}

// Knob names and values with the registry's checks first (KnobError), as
// Session does: the settings, and each axis that is a knob (tradeoff's
// preset and clip-plane axes are checked by its runner).
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

// A str ("A,B", as the CLI's flag takes it) or a list of str.
std::vector<std::string> textList(const std::string& what, const py::handle& value) {
    if (value.is_none()) return {};
    if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
    if (!py::isinstance<py::sequence>(value))
        throw py::value_error("tradeoff: " + what + " must be a str or a list of str, got " +
                              py::str(py::type::of(value).attr("__name__")).cast<std::string>());
    std::vector<std::string> items;
    for (const auto& v : value) {
        if (!py::isinstance<py::str>(v))
            throw py::value_error("tradeoff: " + what + " must hold str, got " +
                                  py::str(py::type::of(v).attr("__name__")).cast<std::string>());
        items.push_back(v.cast<std::string>());
    }
    return items;
}

// The table's rows as tradeoff --csv writes them: one dict a row, its keys
// the CSV's columns in order (point, each axis, camera, metric, buffer,
// error, error_lo, error_hi, frames, frame_gpu_ms, frame_gpu_ms_lo,
// frame_gpu_ms_hi, gpu_ms.<pass>..., pareto); NaN where the CSV is empty.
py::list tradeoffRows(const TradeoffTable& t, bool frontOnly) {
    py::list rows;
    for (const TradeoffRow& r : t.rows) {
        if (frontOnly && !r.pareto) continue;
        py::dict d;
        d["point"] = r.point;
        for (size_t a = 0; a < t.axes.size(); ++a) d[py::str(t.axes[a])] = r.axisValues[a];
        d["camera"] = r.camera;
        d["metric"] = r.metric;
        d["buffer"] = r.buffer;
        d["error"] = r.error;
        d["error_lo"] = r.errorLo;
        d["error_hi"] = r.errorHi;
        d["frames"] = r.frames;
        d["frame_gpu_ms"] = r.frameGpuMs;
        d["frame_gpu_ms_lo"] = r.frameGpuMsLo;
        d["frame_gpu_ms_hi"] = r.frameGpuMsHi;
        for (size_t p = 0; p < t.passes.size(); ++p) d[py::str("gpu_ms." + t.passes[p])] = r.passGpuMs[p];
        d["pareto"] = r.pareto;
        rows.append(d);
    }
    return rows;
}

// Runs `f`, a check whose dw::Error is a bad argument: ValueError (FileError stays dw.Error).
template <typename F>
auto asValueError(F&& f) {
    try {
        return f();
    } catch (const FileError&) {
        throw;
    } catch (const KnobError&) {
        throw;
    } catch (const Error& e) {
        throw py::value_error(e.what());
    }
}

py::dict tradeoffStudy(TradeoffStudyOptions s, const std::optional<py::dict>& sweep, const py::object& presets,
                       const py::object& exclude, std::optional<std::string> csv, std::optional<std::string> json,
                       std::optional<std::string> plot, std::pair<int, int> plotSize, bool quiet,
                       const py::object& progressFn) {
    requirePath(csv, "tradeoff: csv");
    requirePath(json, "tradeoff: json");
    requirePath(plot, "tradeoff: plot");
    const std::vector<BenchKnobAxis> axes = sweepAxes("tradeoff", sweep);
    for (const auto& a : axes) s.sweep.push_back(BenchGrid::sweepText(a));
    s.presets = textList("presets", presets);
    if (s.presets.size() == 1 && s.presets[0].find(',') != std::string::npos)
        s.presets = asValueError([&] { return splitList(s.presets[0], "--presets"); });
    s.exclude = textList("exclude", exclude);
    if (!progressFn.is_none() && !PyCallable_Check(progressFn.ptr()))
        throw py::value_error("tradeoff: progress must be a callable taking a line of text, or None");
    checkKnobs(s.run.sets, axes);
    asValueError([&] { return TradeoffStudy::check(s); });
    refuseNonSceneFile(s.run.sceneSpec());
    // The files, checked before anything is measured (as the CLI's are).
    CommandLine::NamedFiles writes;
    if (csv) writes.emplace_back("csv", *csv);
    if (json) writes.emplace_back("json", *json);
    if (plot) writes.emplace_back("plot", *plot);
    asValueError([&] {
        CommandLine::requireDistinctFiles(writes, CommandLine::inputFiles(s.run));
        if (plot) checkPlotFile(*plot, plotSize.first, plotSize.second);
        return 0;
    });
    if (csv) CommandLine::requireWritable(*csv, "tradeoff CSV");
    if (json) CommandLine::requireWritable(*json, "tradeoff JSON");
    if (plot) CommandLine::requireWritable(*plot, "plot");

    // Progress lines and warnings: to `progress` when given, else to stderr as
    // the CLI writes them (lines not when quiet). Ctrl-C or an exception in
    // `progress` stops the run at its next line.
    bool stopped = false;
    TradeoffStudyProgress progress;
    auto emit = [&](const std::string& line, bool warning) {
        py::gil_scoped_acquire acquire;
        if (stopped) return;
        if (progressFn.is_none()) {
            if (warning || !quiet) std::fprintf(stderr, "%s\n", line.c_str());
            return;
        }
        try {
            progressFn(line);
        } catch (py::error_already_set& e) {
            e.restore();
            stopped = true;
        }
    };
    progress.line = [&](const std::string& line) { emit(line, false); };
    progress.warning = [&](const std::string& line) { emit(line, true); };
    progress.cancelled = [&] {
        py::gil_scoped_acquire acquire;
        if (!stopped && PyErr_CheckSignals() != 0) stopped = true;
        return stopped;
    };

    ExperimentRecord record;
    TradeoffTable table;
    std::string timeAxis;
    bool plotDrawn = true;
    try {
        py::gil_scoped_release release;
        // The scene, --knobs' axes and every axis value: a bad one is ValueError (a missing file dw.Error).
        const TradeoffOptions o = asValueError([&] { return TradeoffStudy::runnerOptions(s); });
        std::unique_ptr<TradeoffRunner> runner = asValueError([&] { return std::make_unique<TradeoffRunner>(o); });
        for (const auto& w : runner->scene().warnings) progress.warning("warning: " + w);
        TradeoffMeasurement measured = WorkbenchSession::tradeoff(*runner, s.aoRays, progress);
        if (progress.cancelled()) throw TradeoffCancelled();  // asked to stop after the last line: nothing written
        table = measured.result.table;
        timeAxis = o.time;
        record = TradeoffStudy::record(s, o, *runner, std::move(measured), "deferred_workbench.tradeoff (Python)");
        if (csv) table.writeCsv(*csv);
        if (json) writeBenchFile(*json, record.json(*json), "tradeoff record");
        if (plot && !table.rows.empty()) {
            // The plot is drawn from a CSV: the one asked for, else a file of its own beside the plot.
            const std::string from = csv ? *csv : *plot + ".csv";
            if (!csv) table.writeCsv(from);
            plotDrawn = runPlotScript("tradeoff_plot.py", "DW_TRADEOFF_PLOT_SCRIPT",
                                      {"--csv", from, "--out", *plot, "--size",
                                       std::to_string(plotSize.first) + "x" + std::to_string(plotSize.second),
                                       "--time", timeAxis},
                                      "tradeoff");
            if (!csv) {
                std::error_code ec;
                std::filesystem::remove(from, ec);
            }
        }
    } catch (const TradeoffCancelled&) {
        if (PyErr_Occurred()) throw py::error_already_set();  // KeyboardInterrupt, or what progress raised
        throw Error("tradeoff: cancelled");
    }
    if (!plotDrawn && PyErr_WarnEx(PyExc_RuntimeWarning,
                                   ("tradeoff: the plot " + *plot + " was not drawn (stderr says why)").c_str(), 1) != 0)
        throw py::error_already_set();
    py::dict d = recordObject(record);
    d["rows"] = tradeoffRows(table, false);
    d["front"] = tradeoffRows(table, true);
    return d;
}

}  // namespace
}  // namespace dw

PYBIND11_MODULE(deferred_workbench, m) {
    using namespace dw;
    m.doc() = "Deferred Workbench: render a scene headless and read any named output as a numpy array";
    requireNumpy();  // fail at import, not at the first render
    m.attr("__version__") = moduleVersion();
    m.attr("__commit__") = moduleCommit();

    static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
    static py::exception<KnobError> knobError(m, "KnobError", PyExc_ValueError);
    static py::exception<WrongThreadError> threadError(m, "ThreadError", error.ptr());
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const KnobError& e) {
            knobError(e.what());
        } catch (const UnknownBufferError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const WrongThreadError& e) {
            threadError(e.what());
        } catch (const Error& e) {
            error(e.what());
        }
    });

    py::class_<WorkbenchSession>(m, "Session",
                                 "One scene rendered headless (EGL) at one size; knobs as the registry declares them.")
        .def(py::init([](const std::string& scene, const py::object& sizeObject, py::object preset,
                         std::optional<py::dict> settings) {
                 const auto size = sizeArg(sizeObject, "Session: size", limits::kSize, "--size");
                 const std::vector<std::string> sets = assignments(settings);
                 const std::vector<std::string> presets = presetList(preset);
                 std::unique_ptr<WorkbenchSession> session;
                 {
                     py::gil_scoped_release release;
                     session = std::make_unique<WorkbenchSession>(scene, size.first, size.second, presets, sets);
                 }
                 // The loader's warnings (an emission clamped to 65000, unknown keys,
                 // ignored glTF features), the lines render prints, as RuntimeWarnings.
                 for (const auto& w : session->session().scene().warnings) warnPython(w);
                 return session;
             }),
             py::arg("scene") = "", py::arg("size") = std::make_pair(1280, 720), py::arg("preset") = py::none(),
             py::arg("settings") = py::none(),
             "scene: a built-in name, a scene .json or a .gltf/.glb ('' : the preset's, else 'default'); size: (w, h);\n"
             "preset: a built-in preset or a preset file, or a list of them applied in order (as repeated --preset); settings: {knob: value} applied last (as --set).")
        .def_property_readonly("size", [](const WorkbenchSession& s) { return py::make_tuple(s.width(), s.height()); })
        .def_property_readonly("scene", &WorkbenchSession::sceneName)
        .def("resize",
             [](WorkbenchSession& s, const py::object& w, const py::object& h) {
                 s.resize(intArg(w, "resize: width", limits::kSize, "--size"), intArg(h, "resize: height", limits::kSize, "--size"));
             },
             py::arg("width"), py::arg("height"))
        .def("get",
             [](const WorkbenchSession& s, const std::string& name) {
                 return knobValue(s.knobs(), *s.knobs().find(s.spec(name).name));
             },
             py::arg("name"), "A knob's value: bool, int, float or the enum's choice as a string.")
        .def("set", [](WorkbenchSession& s, const std::string& name, py::handle value) { s.set(name, knobText(value)); },
             py::arg("name"), py::arg("value"),
             "Sets a knob with the registry's checks (as --set name=value); KnobError carries its message.")
        .def("knobs",
             [](const WorkbenchSession& s, bool text) {
                 py::dict d;
                 const KnobRegistry& k = s.knobs();
                 for (size_t i = 0; i < k.size(); ++i) {
                     const int id = static_cast<int>(i);
                     d[py::str(k.spec(id).name)] = text ? py::object(py::str(k.format(id))) : knobValue(k, id);
                 }
                 return d;
             },
             py::arg("text") = false,
             "Every knob as a dict {name: value}, in the registry's order: bool, int, float or the enum's choice as a\n"
             "str (what get() returns); text=True: each value as a str, as the registry writes it (what follows\n"
             "'name=' on --dump-knobs' lines: 'true', '16', '0.02', 'reinhard').")
        .def("knob_info",
             [](const WorkbenchSession& s, const std::string& name) {
                 const KnobSpec& k = s.spec(name);
                 py::dict d;
                 d["name"] = k.name;
                 d["type"] = k.type == KnobType::Bool ? "bool" : k.type == KnobType::Int ? "int" : k.type == KnobType::Float ? "float" : "enum";
                 d["default"] = k.defaultValue;
                 d["min"] = k.minValue;
                 d["max"] = k.maxValue;
                 d["choices"] = k.choices;
                 d["unit"] = k.unit;
                 d["pass"] = k.pass;
                 d["description"] = k.description;
                 d["tradeoff"] = k.tradeoff;
                 return d;
             },
             py::arg("name"))
        .def("buffers",
             [](const WorkbenchSession& s, bool details) {
                 py::list l;
                 for (const BufferInfo& b : s.buffers()) {
                     if (!details) {
                         l.append(b.name);
                         continue;
                     }
                     py::dict d;
                     d["name"] = b.name;
                     d["kind"] = b.kind;
                     d["pass"] = b.pass;
                     d["description"] = b.description;
                     l.append(d);
                 }
                 return l;
             },
             py::arg("details") = false, "Every named output (as `list buffers`).")
        .def("render",
             [](WorkbenchSession& s, const std::string& buffer, const py::object& framesObject,
                const py::object& warmupObject, std::optional<std::string> record, const py::object& aoRays,
                const py::object& seed, const py::object& threads, bool cache, std::optional<std::string> cacheDir,
                const py::object& progress) {
                 const int frames = intArg(framesObject, "render: frames", limits::kFrames, "render --frames");
                 const int warmup = intArg(warmupObject, "render: warmup", limits::kWarmup, "render --warmup");
                 ReferenceOptions ro = referenceOptions("render", aoRays, seed, threads, cache, cacheDir);
                 requireCallable(progress, "render: progress");
                 requirePath(record, "render: record");
                 s.checkRender(buffer, frames, warmup);
                 if (record) s.checkRecordStart(std::nullopt, "this render()");
                 const bool needsReference = s.isReferenceOutput(buffer);
                 if (needsReference && record)
                     throw py::value_error("render: record= with '" + buffer + "', an output of the CPU reference: "
                                           "a record holds no ao_rays or seed, so replay could not trace it again "
                                           "(render --record refuses it too); record a GPU buffer");
                 // AOV's cost, estimated before the first frame (issue 22), as render prints it.
                 if (const std::string w = s.aovCostWarning(); !w.empty()) warnPython(w);
                 // The reference pass's outputs: the CPU reference of the view as the last frame will have it,
                 // traced (or read from the cache) as `reference` does, then handed to the pass for these frames.
                 std::optional<reference::ReferenceImages> traced;
                 if (needsReference) {
                     const std::uint64_t frame = s.lastFrameOf(frames, warmup);
                     traced = traceReference(progress, [&](reference::ReferenceProgress* p) {
                         ro.progress = p;
                         return s.reference(ro, frame);
                     });
                 }
                 BufferImage image;
                 {
                     py::gil_scoped_release release;
                     image = s.render(buffer, frames, warmup, traced ? &*traced : nullptr);
                     if (record) s.record().write(*record);
                 }
                 // What the last frame lost (the oit pass's fragments), the lines render prints.
                 for (const auto& w : s.frameWarnings()) warnPython(w);
                 return toArray(image);
             },
             py::arg("buffer") = "final", py::arg("frames") = 1, py::arg("warmup") = 0, py::arg("record") = py::none(),
             py::arg("ao_rays") = 64, py::arg("seed") = 1, py::arg("threads") = 0, py::arg("cache") = true,
             py::arg("cache_dir") = py::none(), py::arg("progress") = py::none(),
             "Renders warmup + frames frames and returns `buffer` of the last: H x W x C, top row first;\n"
             "uint8 for 8-bit display outputs (final, tonemap.result, ...), float32 for the rest.\n"
             "record=PATH also writes the experiment record render --record writes (replay measures it again).\n"
             "reference.lbuffer, reference.final, reference.ao and compare.error: the CPU reference of the view is\n"
             "traced first (as `reference`, through its cache; ao_rays, seed, threads, cache, cache_dir as reference()'s)\n"
             "and handed to the reference pass; progress(fraction) is called while it traces, Ctrl-C cancels.\n")
        .def("record",
             [](WorkbenchSession& s, const std::string& path) {
                 requirePath(path, "record: path");
                 ExperimentRecord r;
                 {
                     py::gil_scoped_release release;
                     r = s.record();
                     r.write(path);
                 }
                 return recordObject(r);
             },
             py::arg("path"),
             "Writes the experiment record of the last render() (its buffer, frames, warm-up; the knobs as they are\n"
             "now) to `path`, as render --record does, and returns it as a dict.")
        .def("timings",
             [](const WorkbenchSession& s) {
                 if (!s.timings()) throw Error("no timings yet: call render() first");
                 return timingList(*s.timings());
             },
             "Per pass and span of the last render()'s counted frames: gpu_ms and cpu_ms {median, mean, min, max, count}.")
        .def("probe",
             [](const WorkbenchSession& s, const py::object& x, const py::object& y) {
                 const int px = intArg(x, "probe: x (a column of the " + std::to_string(s.width()) + "x" + std::to_string(s.height()) + " frame)",
                                         OptionRange{0, s.width() - 1});
                 const int py_ = intArg(y, "probe: y (a row of the " + std::to_string(s.width()) + "x" + std::to_string(s.height()) + " frame, 0 at the top)",
                                         OptionRange{0, s.height() - 1});
                 return probeDict(s.probe(px, py_));
             },
             py::arg("x"), py::arg("y"), "Every output and the decoded G-buffer at pixel (x, y), y = 0 at the top.")
        .def("write",
             [](WorkbenchSession& s, const std::string& buffer, const std::string& path) {
                 requirePath(path, "write: path");
                 py::gil_scoped_release release;
                 s.writeBuffer(buffer, path);
             },
             py::arg("buffer"), py::arg("path"), "Writes the last frame's `buffer` as render --out does (.png, .exr).")
        .def("dump_knobs",
             [](const WorkbenchSession& s, const std::string& path) {
                 requirePath(path, "dump_knobs: path");
                 s.writeKnobValues(path);
             },
             py::arg("path"), "Writes what render --dump-knobs writes.")
        .def("reference",
             [](WorkbenchSession& s, const std::string& buffer, const py::object& aoRaysObject, const py::object& seedObject,
                const py::object& threadsObject, bool cache, std::optional<std::string> cacheDir, bool stats,
                std::optional<std::string> out, std::optional<std::string> statsOut,
                const py::object& progress) -> py::object {
                 const auto& names = reference::referenceBuffers();
                 if (std::find(names.begin(), names.end(), buffer) == names.end())
                     throw UnknownBufferError("unknown reference buffer '" + buffer + "' (lbuffer, final, ao or shadow)");
                 ReferenceOptions o = referenceOptions("reference", aoRaysObject, seedObject, threadsObject, cache, cacheDir);
                 const int aoRays = o.aoRays, seed = o.seed;
                 requireCallable(progress, "reference: progress");
                 requirePath(out, "reference: out");
                 requirePath(statsOut, "reference: stats_out");
                 s.requireOwningThread();
                 const reference::ReferenceImages images = traceReference(progress, [&](reference::ReferenceProgress* p) {
                     o.progress = p;
                     return s.reference(o);
                 });
                 if (out) {
                     py::gil_scoped_release release;
                     writeImage(*out, *images.buffer(buffer));
                 }
                 py::dict statsDict = referenceStats(images.stats);
                 if (statsOut) {
                     py::dict file = statsDict;
                     file["scene"] = s.sceneName();
                     file["width"] = s.width();
                     file["height"] = s.height();
                     file["buffer"] = buffer;
                     file["ao_rays_per_pixel"] = aoRays;
                     file["seed"] = seed;
                     writeJsonObject(*statsOut, file);
                 }
                 py::array_t<float> a = toArray(*images.buffer(buffer));
                 if (!stats) return a;
                 return py::make_tuple(a, statsDict);
             },
             py::arg("buffer") = "lbuffer", py::arg("ao_rays") = 64, py::arg("seed") = 1, py::arg("threads") = 0,
             py::arg("cache") = true, py::arg("cache_dir") = py::none(), py::arg("stats") = false,
             py::arg("out") = py::none(), py::arg("stats_out") = py::none(), py::arg("progress") = py::none(),
             "The CPU reference of this view (as `reference`): float32 H x W x C; stats=True: (array, dict).\n"
             "progress(fraction) is called while it traces; Ctrl-C, or an exception in progress, cancels it.\n"
             "out=PATH writes the image as reference --out does (.exr raw, .png in [0, 1]); stats_out=PATH the\n"
             "statistics as JSON (reference --stats-out's figures under the same keys).");

    m.def(
        "bench",
        [](const std::string& scene, const py::object& sizesObject, const py::object& lightsObject,
           std::optional<py::dict> sweep, py::object preset, std::optional<py::dict> settings,
           const py::object& framesObject, const py::object& warmupObject, const py::object& blockObject,
           const py::object& seedObject, std::optional<std::string> csv, std::optional<std::string> json,
           const std::string& ratioOf, const py::object& resamplesObject, const py::object& orbitObject, bool walkthrough,
           std::optional<std::string> recordFile) {
            requirePath(recordFile, "bench: record");
            json = recordPath("bench", json, recordFile);
            BenchOptions o;
            o.run.scene = scene;
            for (const auto& p : presetList(preset)) o.run.addPreset(p);
            o.run.sets = assignments(settings);
            // sizes: None is bench's default, 160x90; a list of (w, h), at least one (as --sizes).
            if (sizesObject.is_none()) {
                o.grid.sizes = {{160, 90}};
            } else {
                if (!py::isinstance<py::list>(sizesObject) && !py::isinstance<py::tuple>(sizesObject))
                    throw py::type_error("bench: sizes must be a list of (width, height), got " + typeName(sizesObject));
                for (const auto& size : sizesObject) o.grid.sizes.push_back(sizeArg(size, "bench: sizes[]", limits::kSize, "--sizes"));
                if (o.grid.sizes.empty())
                    throw py::value_error("bench: sizes is empty (an empty grid measures nothing); None is 160x90");
            }
            // lights: None or []: the scene's own lights; else each count once (as --lights).
            if (!lightsObject.is_none()) {
                if (!py::isinstance<py::list>(lightsObject) && !py::isinstance<py::tuple>(lightsObject))
                    throw py::type_error("bench: lights must be a list of light counts, got " + typeName(lightsObject));
                for (const auto& n : lightsObject) {
                    const int count = intArg(n, "bench: lights[]", limits::kBenchLights, "--lights");
                    if (std::find(o.grid.lights.begin(), o.grid.lights.end(), count) != o.grid.lights.end())
                        throw py::value_error("bench: lights: " + std::to_string(count) + " is given twice (as --lights)");
                    o.grid.lights.push_back(count);
                }
            }
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
                record = WorkbenchSession::benchRecord(std::move(o), ratioOf, resamples, &results,
                                                       [](const std::string& line) {
                                                           py::gil_scoped_acquire acquire;
                                                           warnPython(line);
                                                       });
                if (csv) results.writeCsv(*csv);
                if (json) writeBenchFile(*json, record.json(*json), "bench JSON");
            }
            return recordObject(record);
        },
        py::arg("scene") = "", py::arg("sizes") = py::none(), py::arg("lights") = py::none(),
        py::arg("sweep") = py::none(), py::arg("preset") = py::none(), py::arg("settings") = py::none(),
        py::arg("frames") = 10, py::arg("warmup") = 1, py::arg("block") = 1, py::arg("seed") = 1,
        py::arg("csv") = py::none(), py::arg("json") = py::none(), py::arg("ratio_of") = "frame",
        py::arg("resamples") = 2000, py::arg("orbit") = 0, py::arg("walkthrough") = false, py::arg("record") = py::none(),
        "bench's grid (sizes x lights x sweep {knob: [values]}) in this process. Returns the experiment record\n"
        "bench --json writes, as a dict: scene, knobs, seeds, camera path, grid, build, gl, host, and results (configs with\n"
        "their series' statistics, ratios with 95% intervals and every sample); csv=PATH and record=PATH (or json=PATH,\n"
        "its older name) also write bench --csv's and --record's files; orbit=N and walkthrough=True move the camera as bench's options do.");

    m.def(
        "tradeoff",
        [](const std::string& scene, const py::object& size, py::object preset,
           std::optional<py::dict> settings, std::optional<py::dict> sweep, py::object presets,
           std::optional<std::string> knobs, py::object exclude, const std::string& against, const std::string& metric,
           const std::string& buffer, const py::object& aoRays, std::optional<std::string> mask, const std::string& time,
           const py::object& orbit, bool walkthrough, const py::object& frames, const py::object& warmup,
           const py::object& block, const py::object& resamples, std::optional<std::string> shard,
           std::optional<std::string> csv, std::optional<std::string> json, std::optional<std::string> plot,
           const py::object& plotSizeObject, bool quiet, py::object progress, std::optional<std::string> recordFile) {
            requirePath(recordFile, "tradeoff: record");
            json = recordPath("tradeoff", json, recordFile);
            TradeoffStudyOptions s;
            s.run.scene = scene;
            for (const auto& p : presetList(preset)) s.run.addPreset(p);
            s.run.sets = assignments(settings);
            std::tie(s.run.width, s.run.height) = sizeArg(size, "tradeoff: size", limits::kSize, "tradeoff --size");
            s.knobs = knobs.value_or("");
            s.against = against;
            s.metric = metric;
            s.buffer = buffer;
            s.aoRays = intArg(aoRays, "tradeoff: ao_rays", limits::kAoRays, "tradeoff --ao-rays");
            s.mask = mask.value_or("");
            s.time = time;
            s.orbit = intArg(orbit, "tradeoff: orbit", OptionRange{0, limits::kOrbit.max}, "tradeoff --orbit; 0: fixed");
            s.walkthrough = walkthrough;
            s.frames = intArg(frames, "tradeoff: frames", limits::kFrames, "tradeoff --frames");
            s.warmup = intArg(warmup, "tradeoff: warmup", limits::kWarmup, "tradeoff --warmup");
            s.block = intArg(block, "tradeoff: block", limits::kBlock, "tradeoff --block");
            s.resamples = intArg(resamples, "tradeoff: resamples", limits::kResamples, "tradeoff --resamples");
            s.shard = shard.value_or("");
            const std::pair<int, int> plotSize = sizeArg(plotSizeObject, "tradeoff: plot_size", limits::kPlotSize,
                                                         "tradeoff --plot-size");
            return tradeoffStudy(std::move(s), sweep, presets, exclude, csv, json, plot, plotSize, quiet, progress);
        },
        py::arg("scene") = "", py::arg("size") = std::make_pair(640, 360), py::arg("preset") = py::none(),
        py::arg("settings") = py::none(), py::arg("sweep") = py::none(), py::arg("presets") = py::none(),
        py::arg("knobs") = py::none(), py::arg("exclude") = py::none(), py::arg("against") = "reference",
        py::arg("metric") = "flip", py::arg("buffer") = "final", py::arg("ao_rays") = 64, py::arg("mask") = py::none(),
        py::arg("time") = "frame", py::arg("orbit") = 0, py::arg("walkthrough") = false, py::arg("frames") = 5,
        py::arg("warmup") = 1, py::arg("block") = 1, py::arg("resamples") = 2000, py::arg("shard") = py::none(),
        py::arg("csv") = py::none(), py::arg("json") = py::none(), py::arg("plot") = py::none(),
        py::arg("plot_size") = std::make_pair(800, 600), py::arg("quiet") = false, py::arg("progress") = py::none(),
        py::arg("record") = py::none(),
        "tradeoff's sweep in this process: what each point costs in GPU ms and in error against the CPU reference\n"
        "(or against=\"knob=value,...\"), and the Pareto front. The keywords are tradeoff's options with their\n"
        "defaults (docs/tradeoffs.md): sweep={axis: [values]} (a knob, camera.near or camera.far; the full grid),\n"
        "presets=[...] (an axis), knobs=\"speed/quality\", exclude=[\"axis=v,...\"], metric, buffer, ao_rays, mask,\n"
        "time, orbit, walkthrough, frames, warmup, block, resamples, shard=\"i/n\"; settings={knob: value} as --set.\n"
        "Returns the experiment record tradeoff --json writes, as a dict, with two more keys: rows (the CSV's rows,\n"
        "a dict each: point, each axis, camera, metric, buffer, error, error_lo, error_hi, frames, frame_gpu_ms and\n"
        "its interval, gpu_ms.<pass>, pareto; NaN where the CSV is empty) and front (the rows on the Pareto front).\n"
        "csv=, record= (or json=, its older name) and plot=PATH.png (plot_size=(w, h)) write tradeoff's files; only\n"
        "those asked for.\n"
        "Progress lines go to stderr (quiet=True: none) or to progress(line); Ctrl-C stops the run.\n"
        "A bad argument raises ValueError (KnobError for a knob) with the CLI's message, naming its flag.");

    m.def("compare", &compareArrays, py::arg("reference"), py::arg("test"), py::arg("hdr") = false,
          py::arg("warn_threshold") = 1e-6, py::arg("fail_threshold") = 1e-6, py::arg("maps") = false,
          py::arg("error_map") = py::none(), py::arg("heat_map") = py::none(), py::arg("json") = py::none(),
          "Every metric of `compare` for two arrays of one shape (uint8 read as v / 255): a dict; maps=True adds\n"
          "the per-pixel error maps. error_map=FILE.exr, heat_map=FILE.png and json=PATH write what compare's\n"
          "--error-map, --heat-map and --json write (the JSON: this dict's figures, without maps).");
    m.def(
        "load_image",
        [](const std::string& path) -> py::array {
            requirePath(path, "load_image: path");
            FloatImage image;
            {
                py::gil_scoped_release release;
                image = loadImageFloat(path);
            }
            if (isFloatFormat(path)) return toArray(image);
            BufferImage bytes;
            bytes.width = image.width;
            bytes.height = image.height;
            bytes.channels = image.channels;
            bytes.eightBit = true;
            bytes.bytes.resize(image.pixels.size());
            for (size_t i = 0; i < image.pixels.size(); ++i)
                bytes.bytes[i] = static_cast<std::uint8_t>(std::lround(std::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f));
            return toArray(bytes);
        },
        py::arg("path"), "An image file through the workbench's ImageIO: uint8 for 8-bit formats, float32 for .exr/.hdr/.tif.");
}
