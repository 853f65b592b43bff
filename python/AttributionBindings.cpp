// dw.attribute: tradeoff --attribute in this process (ErrorAttribution):
// where one view's error against the CPU reference comes from.
#include <pybind11/pybind11.h>

#include <cstdio>
#include <thread>

#include "python/Arguments.h"
#include "python/Bindings.h"
#include "python/KnobArguments.h"
#include "python/ProcessContext.h"
#include "python/ValueErrors.h"
#include "headless/CommandLine.h"
#include "renderer/Error.h"
#include "renderer/bench/BenchResults.h"
#include "renderer/study/CachedReferences.h"
#include "renderer/study/ErrorAttribution.h"

namespace py = pybind11;

namespace dw::python {

namespace {

// A run stopped by Ctrl-C (the GIL taken to ask).
struct Interrupted {};

py::dict estimate(double value, double low, double high) {
    py::dict d;
    d["value"] = value;
    d["low"] = low;
    d["high"] = high;
    return d;
}
py::dict estimate(const ErrorEstimate& e) { return estimate(e.value, e.low, e.high); }
py::dict estimate(const ErrorDifference& e) { return estimate(e.value, e.low, e.high); }

py::dict resultObject(const AttributionResult& r) {
    py::dict d;
    d["metric"] = r.metric;
    d["buffer"] = r.buffer;
    d["size"] = py::make_tuple(r.width, r.height);
    d["as_is"] = estimate(r.asIs);
    d["all_exact"] = estimate(r.allExact);
    d["total"] = estimate(r.total);
    py::list families;
    for (const AttributionFamily& f : r.families) {
        py::dict x;
        x["name"] = f.name;
        x["what"] = f.what;
        x["exact"] = f.exact;
        x["kept"] = f.kept;
        x["only_exact"] = estimate(f.onlyExact);
        x["only_approximate"] = estimate(f.onlyApproximate);
        x["removed"] = estimate(f.removed);
        x["added"] = estimate(f.added);
        families.append(x);
    }
    d["families"] = families;
    d["sum_removed"] = r.sumRemoved;
    d["sum_added"] = r.sumAdded;
    d["renders"] = r.renders;
    d["notes"] = r.notes;
    d["table"] = ErrorAttribution::table(r);
    return d;
}

// On the process's GL context, on its thread, without the GIL (the callbacks take it).
AttributionResult measure(ErrorAttribution& attribution, int aoRays, bool quiet, std::vector<std::string>& notes) {
    ProcessContext& pc = processContext();
    if (std::this_thread::get_id() != pc.thread)
        throw Error("attribute must run on the thread that made the GL context (thread " + describeThread(pc.thread) + ")");
    pc.context->makeCurrent();
    const auto say = [quiet](const std::string& line) {
        if (!quiet) std::fprintf(stderr, "%s\n", line.c_str());
    };
    // The notes go into the result (notes, and the table's note: lines), not to stderr.
    const auto warn = [&notes](const std::string& line) { notes.push_back(line.rfind("note: ", 0) == 0 ? line.substr(6) : line); };
    const auto stopIfAsked = [] {
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) throw Interrupted();
    };
    CachedReferences references(aoRays, 1, {say, warn, stopIfAsked});
    py::gil_scoped_release release;
    return attribution.run(references.function(), say);
}

py::dict attribute(const std::string& scene, const py::object& size, py::object preset, std::optional<py::dict> settings,
                   const std::string& metric, const std::string& buffer, const py::object& aoRays,
                   const py::object& resamples, std::optional<std::string> csv, bool quiet) {
    requirePath(csv, "attribute: csv");
    if (csv) CommandLine::requireWritable(*csv, "attribution CSV");  // before the renders, as the CLI checks it
    AttributionOptions o;
    applyRunArguments(o.run, scene, preset, settings);
    std::tie(o.run.width, o.run.height) = sizeArg(size, "attribute: size", limits::kSize, "tradeoff --size");
    o.metric = metric;
    o.buffer = buffer;
    o.resamples = intArg(resamples, "attribute: resamples", limits::kResamples, "tradeoff --resamples");
    const int rays = intArg(aoRays, "attribute: ao_rays", limits::kAoRays, "tradeoff --ao-rays");
    ErrorAttribution attribution = asValueError([&] { return ErrorAttribution(o); });
    AttributionResult r;
    std::vector<std::string> notes;
    try {
        r = measure(attribution, rays, quiet, notes);
    } catch (const Interrupted&) {
        throw py::error_already_set();  // KeyboardInterrupt
    }
    r.notes.insert(r.notes.begin(), notes.begin(), notes.end());
    if (csv) writeBenchFile(*csv, ErrorAttribution::csv(r), "attribution CSV");
    return resultObject(r);
}

}  // namespace

void bindAttribution(py::module_& m) {
    m.def("attribute", &attribute, py::arg("scene") = "", py::arg("size") = std::make_pair(640, 360),
          py::arg("preset") = py::none(), py::arg("settings") = py::none(), py::arg("metric") = "flip",
          py::arg("buffer") = "final", py::arg("ao_rays") = 64, py::arg("resamples") = 2000,
          py::arg("csv") = py::none(), py::arg("quiet") = false,
          "tradeoff --attribute in this process: where one view's error against the CPU reference comes from\n"
          "(docs/tradeoffs.md). For the view at the settings given (scene, preset, settings={knob: value}, size):\n"
          "the error as it is (as_is), with every approximation family at its most accurate setting (all_exact),\n"
          "and for each family its part both ways: removed = as_is - only_exact (the family alone made exact) and\n"
          "added = only_approximate - all_exact (the family alone left as it is), each {value, low, high} with a\n"
          "95% interval paired over 16x16-px tiles. metric is flip or rms (parts of a PSNR or SSIM do not\n"
          "subtract). Returns a dict: metric, buffer, size, as_is, all_exact, total, families (a dict each: name,\n"
          "what, exact, kept, only_exact, only_approximate, removed, added), sum_removed, sum_added, renders,\n"
          "notes, table (the Markdown the CLI prints). csv=PATH writes the CLI's CSV. A bad argument raises\n"
          "ValueError with the CLI's message.");
}

}  // namespace dw::python
