// The Python module deferred_workbench (pybind11): Session over
// WorkbenchSession, images as numpy arrays (H x W x C, top row first; uint8
// for 8-bit display outputs, float32 for everything else), records as dicts.
// This file only converts types and holds the GIL rules: the GIL is released
// while frames render, shaders compile and the CPU reference traces.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>

#include "python/WorkbenchSession.h"
#include "renderer/io/TextFile.h"
#include "renderer/metrics/ImageComparison.h"
#include "renderer/metrics/ComparisonHeatMap.h"

namespace py = pybind11;

namespace dw {
namespace {

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

py::dict compareArrays(const py::array& reference, const py::array& test, bool hdr, double warnThreshold,
                       double failThreshold, bool maps, std::optional<std::string> errorMap,
                       std::optional<std::string> heatMap, std::optional<std::string> json) {
    if (errorMap && !isFloatFormat(*errorMap))
        throw Error("error_map writes float maps: give it an .exr name, got '" + *errorMap + "'");
    const FloatImage a = toFloatImage(reference, "reference");
    const FloatImage b = toFloatImage(test, "test");
    ComparisonSettings settings;
    settings.hdr = hdr;
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

}  // namespace
}  // namespace dw

PYBIND11_MODULE(deferred_workbench, m) {
    using namespace dw;
    m.doc() = "Deferred Workbench: render a scene headless and read any named output as a numpy array";

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
        .def(py::init([](const std::string& scene, std::pair<int, int> size, std::optional<std::string> preset,
                         std::optional<py::dict> settings) {
                 std::vector<std::string> sets;
                 if (settings)
                     for (const auto& [k, v] : *settings) sets.push_back(py::str(k).cast<std::string>() + "=" + knobText(v));
                 py::gil_scoped_release release;
                 return std::make_unique<WorkbenchSession>(scene, size.first, size.second, preset.value_or(""), sets);
             }),
             py::arg("scene") = "", py::arg("size") = std::make_pair(1280, 720), py::arg("preset") = py::none(),
             py::arg("settings") = py::none(),
             "scene: a built-in name, a scene .json or a .gltf/.glb ('' : the preset's, else 'default'); size: (w, h);\n"
             "preset: a built-in preset or a preset file; settings: {knob: value} applied last (as --set).")
        .def_property_readonly("size", [](const WorkbenchSession& s) { return py::make_tuple(s.width(), s.height()); })
        .def_property_readonly("scene", &WorkbenchSession::sceneName)
        .def("resize", [](WorkbenchSession& s, int w, int h) { s.resize(w, h); }, py::arg("width"), py::arg("height"))
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
             "Every knob's value; text=True: as --dump-knobs writes it.")
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
             [](WorkbenchSession& s, const std::string& buffer, int frames, int warmup, std::optional<std::string> record) {
                 BufferImage image;
                 {
                     py::gil_scoped_release release;
                     image = s.render(buffer, frames, warmup);
                     if (record) s.record().write(*record);
                 }
                 return toArray(image);
             },
             py::arg("buffer") = "final", py::arg("frames") = 1, py::arg("warmup") = 0, py::arg("record") = py::none(),
             "Renders warmup + frames frames and returns `buffer` of the last: H x W x C, top row first;\n"
             "uint8 for 8-bit display outputs (final, tonemap.result, ...), float32 for the rest.\n"
             "record=PATH also writes the experiment record render --record writes (replay measures it again).")
        .def("record",
             [](WorkbenchSession& s, const std::string& path) {
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
        .def("probe", [](const WorkbenchSession& s, int x, int y) { return probeDict(s.probe(x, y)); }, py::arg("x"),
             py::arg("y"), "Every output and the decoded G-buffer at pixel (x, y), y = 0 at the top.")
        .def("write",
             [](WorkbenchSession& s, const std::string& buffer, const std::string& path) {
                 py::gil_scoped_release release;
                 s.writeBuffer(buffer, path);
             },
             py::arg("buffer"), py::arg("path"), "Writes the last frame's `buffer` as render --out does (.png, .exr).")
        .def("dump_knobs", &WorkbenchSession::writeKnobValues, py::arg("path"), "Writes what render --dump-knobs writes.")
        .def("reference",
             [](WorkbenchSession& s, const std::string& buffer, int aoRays, int seed, int threads, bool cache,
                std::optional<std::string> cacheDir, bool stats, std::optional<std::string> out,
                std::optional<std::string> statsOut) -> py::object {
                 const auto& names = reference::referenceBuffers();
                 if (std::find(names.begin(), names.end(), buffer) == names.end())
                     throw UnknownBufferError("unknown reference buffer '" + buffer + "' (lbuffer, final, ao or shadow)");
                 s.requireOwningThread();
                 ReferenceOptions o;
                 o.aoRays = aoRays;
                 o.seed = seed;
                 o.threads = threads;
                 o.useCache = cache;
                 o.cacheDirectory = cacheDir.value_or("");
                 reference::ReferenceImages images;
                 {
                     py::gil_scoped_release release;
                     images = s.reference(o);
                 }
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
             py::arg("out") = py::none(), py::arg("stats_out") = py::none(),
             "The CPU reference of this view (as `reference`): float32 H x W x C; stats=True: (array, dict).\n"
             "out=PATH writes the image as reference --out does (.exr raw, .png in [0, 1]); stats_out=PATH the\n"
             "statistics as JSON (reference --stats-out's figures under the same keys).");

    m.def(
        "bench",
        [](const std::string& scene, std::vector<std::pair<int, int>> sizes, std::vector<int> lights,
           std::optional<py::dict> sweep, std::optional<std::string> preset, std::optional<py::dict> settings,
           int frames, int warmup, int block, int seed, std::optional<std::string> csv, std::optional<std::string> json,
           const std::string& ratioOf, int resamples, int orbit, bool walkthrough) {
            BenchOptions o;
            o.run.scene = scene;
            o.run.setPreset(preset.value_or(""));
            if (settings)
                for (const auto& [k, v] : *settings) o.run.sets.push_back(py::str(k).cast<std::string>() + "=" + knobText(v));
            o.grid.sizes = sizes.empty() ? std::vector<std::pair<int, int>>{{160, 90}} : sizes;
            for (int n : lights)
                if (n < 0 || n > 1000000)
                    throw py::value_error("bench: lights must be between 0 and 1000000, got " + std::to_string(n));
            o.grid.lights = lights;
            if (sweep)
                for (const auto& [k, values] : *sweep) {
                    BenchKnobAxis axis;
                    axis.knob = py::str(k).cast<std::string>();
                    // As the CLI's --sweep: a list of values, at least one (an empty axis is an empty grid).
                    if (py::isinstance<py::str>(values) || !py::isinstance<py::sequence>(values))
                        throw py::value_error("bench: sweep['" + axis.knob + "'] must be a list of values, got " +
                                              py::str(py::type::of(values).attr("__name__")).cast<std::string>());
                    for (const auto& v : values) axis.values.push_back(knobText(v));
                    if (axis.values.empty())
                        throw py::value_error("bench: sweep['" + axis.knob + "'] has no values (an empty axis leaves no configuration)");
                    o.grid.knobAxes.push_back(axis);
                }
            // Knob names and values with the registry's checks first (KnobError), as Session does.
            KnobRegistry declared = RunConfig::declaredKnobs();
            try {
                for (const std::string& a : o.run.sets) declared.applyAssignment(a);
                for (const BenchKnobAxis& axis : o.grid.knobAxes)
                    for (const std::string& v : axis.values) declared.setFromString(axis.knob, v);
            } catch (const Error& e) {
                throw KnobError(e.what());
            }
            if (frames < 1 || warmup < 0 || block < 1 || seed < 0)
                throw Error("bench: frames and block must be at least 1, warmup and seed not negative");
            o.frames = frames;
            o.warmup = warmup;
            o.block = block;
            o.seed = static_cast<std::uint32_t>(seed);
            if (resamples < 100) throw Error("bench: resamples must be at least 100");
            if (orbit < 0 || (orbit > 0 && walkthrough)) throw Error("bench: orbit takes a pose count >= 0, not with walkthrough");
            o.orbit = orbit;
            o.walkthrough = walkthrough;
            BenchResults results;
            ExperimentRecord record;
            {
                py::gil_scoped_release release;
                record = WorkbenchSession::benchRecord(std::move(o), ratioOf, resamples, &results);
                if (csv) results.writeCsv(*csv);
                if (json) writeBenchFile(*json, record.json(*json), "bench JSON");
            }
            return recordObject(record);
        },
        py::arg("scene") = "", py::arg("sizes") = std::vector<std::pair<int, int>>{}, py::arg("lights") = std::vector<int>{},
        py::arg("sweep") = py::none(), py::arg("preset") = py::none(), py::arg("settings") = py::none(),
        py::arg("frames") = 10, py::arg("warmup") = 1, py::arg("block") = 1, py::arg("seed") = 1,
        py::arg("csv") = py::none(), py::arg("json") = py::none(), py::arg("ratio_of") = "frame",
        py::arg("resamples") = 2000, py::arg("orbit") = 0, py::arg("walkthrough") = false,
        "bench's grid (sizes x lights x sweep {knob: [values]}) in this process. Returns the experiment record\n"
        "bench --json writes, as a dict: scene, knobs, seeds, camera path, grid, build, gl, host, and results (configs with\n"
        "their series' statistics, ratios with 95% intervals and every sample); csv=PATH and json=PATH also write\n"
        "bench --csv's and --json's files; orbit=N and walkthrough=True move the camera as bench's options do.");

    m.def("compare", &compareArrays, py::arg("reference"), py::arg("test"), py::arg("hdr") = false,
          py::arg("warn_threshold") = 1e-6, py::arg("fail_threshold") = 1e-6, py::arg("maps") = false,
          py::arg("error_map") = py::none(), py::arg("heat_map") = py::none(), py::arg("json") = py::none(),
          "Every metric of `compare` for two arrays of one shape (uint8 read as v / 255): a dict; maps=True adds\n"
          "the per-pixel error maps. error_map=FILE.exr, heat_map=FILE.png and json=PATH write what compare's\n"
          "--error-map, --heat-map and --json write (the JSON: this dict's figures, without maps).");
    m.def(
        "load_image",
        [](const std::string& path) -> py::array {
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
