// dw.Session over WorkbenchSession: knobs, buffers, frames and what they
// measured, as Python objects (images through python/Arrays.h).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "python/Arguments.h"
#include "python/Arrays.h"
#include "python/Bindings.h"
#include "python/KnobArguments.h"
#include "python/ReferenceTrace.h"
#include "python/Warnings.h"
#include "renderer/OptionLimits.h"

namespace py = pybind11;

namespace dw::python {
namespace {

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

py::dict surfaceDict(const SurfaceSample& s) {
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
    return surface;
}

py::dict probeDict(const ProbeResult& p) {
    py::dict d;
    d["x"] = p.x;
    d["y"] = p.y;
    d["inside"] = p.inside;
    d["surface"] = surfaceDict(p.surface);
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

std::unique_ptr<WorkbenchSession> makeSession(const std::string& scene, const py::object& sizeObject, py::object preset,
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
}

py::dict knobsDict(const WorkbenchSession& s, bool text) {
    py::dict d;
    const KnobRegistry& k = s.knobs();
    for (size_t i = 0; i < k.size(); ++i) {
        const int id = static_cast<int>(i);
        d[py::str(k.spec(id).name)] = text ? py::object(py::str(k.format(id))) : knobValue(k, id);
    }
    return d;
}

py::dict knobInfo(const WorkbenchSession& s, const std::string& name) {
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
}

py::list bufferList(const WorkbenchSession& s, bool details) {
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
}

py::array render(WorkbenchSession& s, const std::string& buffer, const py::object& framesObject,
                 const py::object& warmupObject, std::optional<std::string> record, const py::object& aoRays,
                 const py::object& seed, const py::object& threads, bool cache, std::optional<std::string> cacheDir,
                 const py::object& progress, const py::object& spp, const py::object& sceneTime) {
    const int frames = intArg(framesObject, "render: frames", limits::kFrames, "render --frames");
    std::optional<double> time;
    if (!sceneTime.is_none()) time = numberArg(sceneTime, "render: scene_time", limits::kSceneTime, "render --scene-time");
    const int warmup = intArg(warmupObject, "render: warmup", limits::kWarmup, "render --warmup");
    ReferenceOptions ro = referenceOptions("render", aoRays, seed, threads, cache, cacheDir);
    ro.pixelSamples = intArg(spp, "render: spp", limits::kPixelSamples, "render --spp");
    requireCallable(progress, "render: progress");
    requirePath(record, "render: record");
    s.checkRender(buffer, frames, warmup);
    if (record) s.checkRecordStart(std::nullopt, "this render()");
    if (time) s.setSceneTime(*time);
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
}

py::dict probe(const WorkbenchSession& s, const py::object& x, const py::object& y) {
    const std::string frame = std::to_string(s.width()) + "x" + std::to_string(s.height()) + " frame";
    const int px = intArg(x, "probe: x (a column of the " + frame + ")", OptionRange{0, s.width() - 1});
    const int py_ = intArg(y, "probe: y (a row of the " + frame + ", 0 at the top)", OptionRange{0, s.height() - 1});
    return probeDict(s.probe(px, py_));
}

// Knobs and buffers: what a session is made of and how it is set.
void bindKnobs(SessionClass& c) {
    c.def_property_readonly("size", [](const WorkbenchSession& s) { return py::make_tuple(s.width(), s.height()); })
        .def_property_readonly("scene", &WorkbenchSession::sceneName)
        .def_property(
            "scene_time", &WorkbenchSession::sceneTime,
            [](WorkbenchSession& s, const py::object& t) {
                s.setSceneTime(numberArg(t, "scene_time", limits::kSceneTime, "render --scene-time"));
            },
            "The scene time (seconds) the scene's glTF animation is posed at for render() and reference().")
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
        .def("knobs", &knobsDict, py::arg("text") = false,
             "Every knob as a dict {name: value}, in the registry's order: bool, int, float or the enum's choice as a\n"
             "str (what get() returns); text=True: each value as a str, as the registry writes it (what follows\n"
             "'name=' on --dump-knobs' lines: 'true', '16', '0.02', 'reinhard').")
        .def("knob_info", &knobInfo, py::arg("name"))
        .def("buffers", &bufferList, py::arg("details") = false, "Every named output (as `list buffers`).");
}

// Frames: render, and what the last one measured and holds.
void bindFrames(SessionClass& c) {
    c.def("render", &render, py::arg("buffer") = "final", py::arg("frames") = 1, py::arg("warmup") = 0,
          py::arg("record") = py::none(), py::arg("ao_rays") = 64, py::arg("seed") = 1, py::arg("threads") = 0,
          py::arg("cache") = true, py::arg("cache_dir") = py::none(), py::arg("progress") = py::none(),
          py::arg("spp") = 1, py::arg("scene_time") = py::none(),
          "Renders warmup + frames frames and returns `buffer` of the last: H x W x C, top row first;\n"
          "scene_time=T (seconds, as render --scene-time) poses the scene's glTF animation at T first and\n"
          "stays (the `scene_time` property; reference() traces the same pose).\n"
          "uint8 for 8-bit display outputs (final, tonemap.result, ...), float32 for the rest.\n"
          "record=PATH also writes the experiment record render --record writes (replay measures it again).\n"
          "reference.lbuffer, reference.final, reference.ao, reference.spp_error and compare.error: the CPU reference\n"
          "of the view is traced first (as `reference`, through its cache; ao_rays, seed, spp, threads, cache,\n"
          "cache_dir as reference()'s; reference.spp_error is 0 at spp=1)\n"
          "and handed to the reference pass; progress(fraction) is called while it traces, Ctrl-C cancels.\n")
        .def("timings",
             [](const WorkbenchSession& s) {
                 if (!s.timings()) throw Error("no timings yet: call render() first");
                 return timingList(*s.timings());
             },
             "Per pass and span of the last render()'s counted frames: gpu_ms and cpu_ms {median, mean, min, max, count}.")
        .def("probe", &probe, py::arg("x"), py::arg("y"),
             "Every output and the decoded G-buffer at pixel (x, y), y = 0 at the top.")
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
             py::arg("path"), "Writes what render --dump-knobs writes.");
}

}  // namespace

SessionClass bindSession(py::module_& m) {
    SessionClass c(m, "Session", "One scene rendered headless (EGL) at one size; knobs as the registry declares them.");
    c.def(py::init(&makeSession), py::arg("scene") = "", py::arg("size") = std::make_pair(1280, 720),
          py::arg("preset") = py::none(), py::arg("settings") = py::none(),
          "scene: a built-in name, a scene .json or a .gltf/.glb ('' : the preset's, else 'default'); size: (w, h);\n"
          "preset: a built-in preset or a preset file, or a list of them applied in order (as repeated --preset); settings: {knob: value} applied last (as --set).");
    bindKnobs(c);
    bindFrames(c);
    return c;
}

}  // namespace dw::python
