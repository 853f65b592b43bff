// dw.tradeoff: tradeoff's sweep in this process, its arguments checked by
// TradeoffStudy as the CLI's are, its files written as tradeoff writes them,
// its record returned as a dict with the table's rows and the Pareto front.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "headless/CommandLine.h"
#include "headless/PlotScript.h"
#include "python/Arguments.h"
#include "python/Bindings.h"
#include "python/KnobArguments.h"
#include "python/ProcessContext.h"
#include "python/ValueErrors.h"
#include "python/Records.h"
#include "renderer/OptionLimits.h"
#include "renderer/bench/BudgetPick.h"
#include "renderer/study/BudgetSearch.h"
#include "renderer/study/TradeoffStudy.h"

namespace py = pybind11;

namespace dw::python {
namespace {

// The files tradeoff= writes (csv=, record= or json=, plot= at plot_size=); none: not asked for.
struct TradeoffFiles {
    std::optional<std::string> csv, json, plot;
    std::pair<int, int> plotSize;
};

// What a measured sweep leaves: its record and table, and whether the plot asked for was drawn.
struct TradeoffOutcome {
    ExperimentRecord record;
    TradeoffTable table;
    BudgetPick pick;
    std::optional<BudgetSearchResult> search;  // search=True
    bool plotDrawn = true;
};

// A str ("A,B", as the CLI's flag takes it) or a list of str.
std::vector<std::string> textList(const std::string& what, const py::handle& value) {
    if (value.is_none()) return {};
    if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
    if (!py::isinstance<py::sequence>(value))
        throw py::value_error("tradeoff: " + what + " must be a str or a list of str, got " + typeName(value));
    std::vector<std::string> items;
    for (const auto& v : value) {
        if (!py::isinstance<py::str>(v)) throw py::value_error("tradeoff: " + what + " must hold str, got " + typeName(v));
        items.push_back(v.cast<std::string>());
    }
    return items;
}

// The table's rows as tradeoff --csv writes them: one dict a row, its keys
// the CSV's columns in order (point, each axis, camera, metric, buffer,
// error, error_lo, error_hi, frames, frame_gpu_ms, frame_gpu_ms_lo,
// frame_gpu_ms_hi, gpu_ms.<pass>..., the counters when counted: fragments,
// fragments.<pass>, ..., bytes.<pass>..., pareto, time, time_ms, time_ms_lo,
// time_ms_hi, front, dominated_by (a list of points), tied_with (a list of
// (point, "time"|"error"|"both")), pick, gpu_mem_peak_mib); NaN where the
// CSV is empty.
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
        for (int i = 0; t.counted && i < PassCounts::kCount; ++i) {
            const std::string name = PassCounts::name(i);
            d[py::str(name)] = r.frameCounts[static_cast<size_t>(i)];
            for (size_t p = 0; p < t.passes.size(); ++p)
                if (TradeoffTable::hasCounterColumns(t.passes[p]))
                    d[py::str(name + "." + t.passes[p])] =
                        p < r.passCounts.size() ? r.passCounts[p][static_cast<size_t>(i)] : NAN;
        }
        d["pareto"] = r.pareto;
        d["time"] = t.time;
        d["time_ms"] = r.timeMs;
        d["time_ms_lo"] = r.timeMsLo;
        d["time_ms_hi"] = r.timeMsHi;
        d["front"] = r.front;
        d["dominated_by"] = r.dominatedBy;
        py::list ties;
        for (const auto& [point, axes] : r.tiedWith) ties.append(py::make_tuple(point, axes));
        d["tied_with"] = ties;
        d["pick"] = r.pick;
        d["gpu_mem_peak_mib"] = r.gpuMemPeakMib;  // the CSV's last column (NaN: not measured)
        rows.append(d);
    }
    return rows;
}

// The budget's pick: {budget_ms (or budget: a counter's), point (None when none fits), row (its row),
// tied (points that fit and cannot be told apart from it in error), fitting,
// cheapest (with none fitting), lines (what the CLI prints)}.
py::dict pickObject(const TradeoffTable& t, const BudgetPick& pick, const std::string& budgetKey) {
    py::dict d;
    d[py::str(budgetKey)] = pick.budgetMs;
    d["point"] = pick.point >= 0 ? py::object(py::int_(pick.point)) : py::object(py::none());
    d["tied"] = pick.tied;
    d["fitting"] = pick.fitting;
    d["cheapest"] = pick.cheapest >= 0 ? py::object(py::int_(pick.cheapest)) : py::object(py::none());
    d["lines"] = pick.lines;
    py::object row = py::none();
    for (const py::handle r : tradeoffRows(t, false))
        if (py::cast<std::string>(r["pick"]) == "pick") row = py::reinterpret_borrow<py::object>(r);
    d["row"] = row;
    return d;
}

// The files, checked before anything is measured (as the CLI's are):
// distinct from each other and from the run's inputs, the plot drawable, each writable.
void checkWrites(const TradeoffStudyOptions& s, const TradeoffFiles& f) {
    CommandLine::NamedFiles writes;
    if (f.csv) writes.emplace_back("csv", *f.csv);
    if (f.json) writes.emplace_back("json", *f.json);
    if (f.plot) writes.emplace_back("plot", *f.plot);
    asValueError([&] {
        CommandLine::requireDistinctFiles(writes, CommandLine::inputFiles(s.run));
        if (f.plot) checkPlotFile(*f.plot, f.plotSize.first, f.plotSize.second);
        return 0;
    });
    if (f.csv) CommandLine::requireWritable(*f.csv, "tradeoff CSV");
    if (f.json) CommandLine::requireWritable(*f.json, "tradeoff JSON");
    if (f.plot) CommandLine::requireWritable(*f.plot, "plot");
}

// studies=: [{knob: value or [values]}, ...] (named as --study names them)
// or {name: {knob: value or [values]}, ...}, the shapes a --study-file holds
// (TradeoffStudies); None: none. Anything else is ValueError.
std::vector<TradeoffStudySpec> studyList(const py::object& studies) {
    std::vector<TradeoffStudySpec> out;
    if (studies.is_none()) return out;
    auto one = [&](const py::handle& knobs, const std::string& name) {
        if (!py::isinstance<py::dict>(knobs))
            throw py::value_error("tradeoff: studies: each study is a dict {knob: value or [values]}, got " +
                                  std::string(py::str(py::repr(knobs))));
        TradeoffStudySpec spec;
        spec.name = name;
        spec.origin = "studies";
        for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(knobs)) {
            TradeoffStudySpec::Knob knob{std::string(py::str(k)), {}};
            if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v))
                for (const auto& x : v) knob.values.push_back(knobText(x));
            else
                knob.values.push_back(knobText(v));
            spec.knobs.push_back(std::move(knob));
        }
        out.push_back(std::move(spec));
    };
    if (py::isinstance<py::dict>(studies)) {
        for (const auto& [name, knobs] : py::reinterpret_borrow<py::dict>(studies)) one(knobs, py::str(name));
    } else if (py::isinstance<py::list>(studies) || py::isinstance<py::tuple>(studies)) {
        for (const auto& knobs : studies) one(knobs, "");
    } else {
        throw py::value_error("tradeoff: studies: expected a list of {knob: value or [values]} or a dict {name: {...}}");
    }
    if (out.empty()) throw py::value_error("tradeoff: studies: no studies (None for a sweep)");
    return out;
}

// The study's sweep, presets and exclusions from their keywords, and every
// check the CLI makes before it measures (TradeoffStudy::check, the scene
// file, the files); bad ones are ValueError (KnobError for a knob).
void readSweep(TradeoffStudyOptions& s, const std::optional<py::dict>& sweep, const py::object& presets,
               const py::object& exclude, const py::object& progressFn) {
    s.sweep = sweepAxes("tradeoff", sweep);
    const std::vector<BenchKnobAxis>& axes = s.sweep;
    s.presets = textList("presets", presets);
    if (s.presets.size() == 1 && s.presets[0].find(',') != std::string::npos)
        s.presets = asValueError([&] { return splitList(s.presets[0], "--presets"); });
    s.exclude = textList("exclude", exclude);
    if (!progressFn.is_none() && !PyCallable_Check(progressFn.ptr()))
        throw py::value_error("tradeoff: progress must be a callable taking a line of text, or None");
    checkKnobs(s.run.sets, axes);
    asValueError([&] { return TradeoffTable::timeTerms(s.time); });
    asValueError([&] { return TradeoffStudy::check(s); });
    refuseNonSceneFile(s.run.sceneSpec());
}

// Progress lines and warnings: to `progress` when given, else to stderr as
// the CLI writes them (lines not when quiet). Ctrl-C or an exception in
// `progress` stops the run at its next line (stopped(); the exception stays
// set for the caller to raise). Each call takes the GIL.
class ProgressSink {
public:
    ProgressSink(const py::object& progressFn, bool quiet) : progressFn_(progressFn), quiet_(quiet) {}
    ProgressSink(const ProgressSink&) = delete;
    ProgressSink& operator=(const ProgressSink&) = delete;

    // The study's callbacks; they refer to this sink, which must outlive them.
    TradeoffStudyProgress progress() {
        TradeoffStudyProgress p;
        p.line = [this](const std::string& line) { emit(line, false); };
        p.warning = [this](const std::string& line) { emit(line, true); };
        p.cancelled = [this] {
            py::gil_scoped_acquire acquire;
            if (!stopped_ && PyErr_CheckSignals() != 0) stopped_ = true;
            return stopped_;
        };
        return p;
    }

private:
    void emit(const std::string& line, bool warning) {
        py::gil_scoped_acquire acquire;
        if (stopped_) return;
        if (progressFn_.is_none()) {
            if (warning || !quiet_) std::fprintf(stderr, "%s\n", line.c_str());
            return;
        }
        try {
            progressFn_(line);
        } catch (py::error_already_set& e) {
            e.restore();
            stopped_ = true;
        }
    }

    const py::object& progressFn_;
    const bool quiet_;
    bool stopped_ = false;
};

// Draws `f.plot` from the table with scripts/tradeoff_plot.py, as tradeoff
// does; false when it was not drawn (stderr says why).
bool drawPlot(const TradeoffTable& table, const TradeoffFiles& f, const std::string& timeAxis, const std::string& cost) {
    // The plot is drawn from a CSV: the one asked for, else a file of its own beside the plot.
    const std::string from = f.csv ? *f.csv : *f.plot + ".csv";
    if (!f.csv) table.writeCsv(from);
    const bool drawn = runPlotScript("tradeoff_plot.py", "DW_TRADEOFF_PLOT_SCRIPT",
                                     {"--csv", from, "--out", *f.plot, "--size",
                                      std::to_string(f.plotSize.first) + "x" + std::to_string(f.plotSize.second),
                                      "--time", timeAxis, "--cost", cost},
                                     "tradeoff");
    if (!f.csv) {
        std::error_code ec;
        std::filesystem::remove(from, ec);
    }
    return drawn;
}

// search=True: BudgetSearch from the current settings (the CLI's --search); its table, record and files.
TradeoffOutcome measureSearch(const TradeoffStudyOptions& s, const TradeoffOptions& o, const TradeoffRunner& start,
                              const TradeoffStudyProgress& progress, const TradeoffFiles& f) {
    BudgetSearchOptions bo;
    bo.base = o;
    bo.maxEvals = s.maxEvals;
    bo.aoRays = s.aoRays;
    bo.referencePixels = TradeoffStudy::referencePixels(s);
    TradeoffOutcome out;
    out.search = WorkbenchSession::search(bo, progress);
    if (progress.cancelled()) throw TradeoffCancelled();
    TradeoffMeasurement measured;
    measured.result = BudgetSearch::asResult(*out.search);
    measured.machine = out.search->last.machine;
    measured.machine.emplace_back("gl_platform", processContext().context->platform());
    out.table = out.search->table;
    out.record = TradeoffStudy::record(s, o, start, std::move(measured), "deferred_workbench.tradeoff (Python, search)");
    if (f.csv) out.table.writeCsv(*f.csv);
    if (f.json) writeBenchFile(*f.json, out.record.json(*f.json), "tradeoff record");
    return out;  // no plot: the rows are evaluations of different steps, each with its own front and pick
}

// search's result: found {knob: value}, evaluation (its row's point), fits, evaluations, converged, grid_points,
// steps [{step, knob, values, first_evaluation, evaluations, outcome}], lines (what the CLI prints).
py::dict searchObject(const BudgetSearchResult& r) {
    py::dict found, d;
    for (size_t k = 0; k < r.knobs.size(); ++k) found[py::str(r.knobs[k])] = r.found[k];
    py::list steps;
    for (const auto& st : r.steps) {
        py::dict one;
        one["step"] = st.step;
        one["knob"] = st.knob;
        one["values"] = st.values;
        one["first_evaluation"] = st.firstEvaluation;
        one["evaluations"] = st.evaluations;
        one["outcome"] = st.outcome;
        steps.append(one);
    }
    d["found"] = found;
    d["evaluation"] = r.foundEvaluation >= 0 ? py::object(py::int_(r.foundEvaluation)) : py::object(py::none());
    d["fits"] = r.fits;
    d["evaluations"] = r.evaluations;
    d["converged"] = r.converged;
    d["grid_points"] = r.gridPoints;
    d["steps"] = steps;
    d["lines"] = r.lines;
    return d;
}

// Measures the study on the process's GL context and writes the files asked
// for. Runs without the GIL (the callbacks take it). TradeoffCancelled when
// asked to stop, with nothing written.
TradeoffOutcome measure(const TradeoffStudyOptions& s, const TradeoffStudyProgress& progress, const TradeoffFiles& f) {
    // The scene, --knobs' axes and every axis value: a bad one is ValueError (a missing file dw.Error).
    const TradeoffOptions o = asValueError([&] { return TradeoffStudy::runnerOptions(s); });
    std::unique_ptr<TradeoffRunner> runner = asValueError([&] { return std::make_unique<TradeoffRunner>(o); });
    for (const auto& w : runner->scene().warnings) progress.warning("warning: " + w);
    if (s.search) return measureSearch(s, o, *runner, progress, f);
    TradeoffMeasurement measured = WorkbenchSession::tradeoff(*runner, s.aoRays, TradeoffStudy::referencePixels(s), progress);
    if (progress.cancelled()) throw TradeoffCancelled();  // asked to stop after the last line: nothing written
    TradeoffOutcome out;
    out.table = measured.result.table;
    out.pick = measured.result.pick;
    out.record = TradeoffStudy::record(s, o, *runner, std::move(measured), "deferred_workbench.tradeoff (Python)");
    if (f.csv) out.table.writeCsv(*f.csv);
    if (f.json) writeBenchFile(*f.json, out.record.json(*f.json), "tradeoff record");
    if (f.plot && !out.table.rows.empty()) out.plotDrawn = drawPlot(out.table, f, o.time, o.cost);
    return out;
}

py::dict tradeoffStudy(TradeoffStudyOptions s, const std::optional<py::dict>& sweep, const py::object& presets,
                       const py::object& exclude, const TradeoffFiles& files, bool quiet, const py::object& progressFn) {
    requirePath(files.csv, "tradeoff: csv");
    requirePath(files.json, "tradeoff: json");
    requirePath(files.plot, "tradeoff: plot");
    readSweep(s, sweep, presets, exclude, progressFn);
    checkWrites(s, files);
    ProgressSink sink(progressFn, quiet);
    const TradeoffStudyProgress progress = sink.progress();
    TradeoffOutcome outcome;
    try {
        py::gil_scoped_release release;
        outcome = measure(s, progress, files);
    } catch (const TradeoffCancelled&) {
        if (PyErr_Occurred()) throw py::error_already_set();  // KeyboardInterrupt, or what progress raised
        throw Error("tradeoff: cancelled");
    } catch (const FileError&) {
        throw;
    } catch (const Error& e) {  // a time= the pipeline has no pass of (found once it runs): a bad argument
        const std::string what = e.what();
        if (what.rfind("--time ", 0) == 0) throw py::value_error(what);
        throw;
    }
    if (!outcome.plotDrawn &&
        PyErr_WarnEx(PyExc_RuntimeWarning, ("tradeoff: the plot " + *files.plot + " was not drawn (stderr says why)").c_str(),
                     1) != 0)
        throw py::error_already_set();
    py::dict d = recordObject(outcome.record);
    d["rows"] = tradeoffRows(outcome.table, false);
    d["front"] = tradeoffRows(outcome.table, true);
    d["front_rule"] = outcome.table.frontRules.count(BudgetPicker::shownCamera(outcome.table))
                          ? outcome.table.frontRules.at(BudgetPicker::shownCamera(outcome.table))
                          : std::string();
    if (outcome.search)
        d["search"] = searchObject(*outcome.search);
    else if (s.budgetMs || s.budget)
        d["pick"] = pickObject(outcome.table, outcome.pick, s.budgetMs ? "budget_ms" : "budget");
    return d;
}

// budget_ms= / budget=: None, or a number (an int or a float; True is not
// 1): TypeError for anything else; its range is TradeoffStudy::check's (ValueError).
std::optional<double> optionalNumber(const py::object& value, const std::string& name, const std::string& flag) {
    if (value.is_none()) return std::nullopt;
    const std::string expected = name + " must be a number (as " + flag + ") or None, got ";
    if (PyBool_Check(value.ptr()) || PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr()))
        throw py::type_error(expected + typeName(value));
    const double v = PyFloat_AsDouble(value.ptr());
    if (v == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        throw py::type_error(expected + typeName(value));
    }
    return v;
}

py::dict tradeoff(const std::string& scene, const py::object& size, py::object preset, std::optional<py::dict> settings,
                  std::optional<py::dict> sweep, py::object presets, std::optional<std::string> knobs,
                  const py::object& studies, py::object exclude, const std::string& against, const std::string& metric,
                  const std::string& buffer,
                  const py::object& aoRays, const py::object& refSpp, const std::string& refFilter,
                  std::optional<std::string> mask, const std::string& time,
                  const std::string& cost, const py::object& budgetMsObject, const py::object& budgetObject,
                  const py::object& orbit, const py::object& orbitDegrees, bool walkthrough, const py::object& frames, const py::object& warmup,
                  const py::object& block, const py::object& resamples, std::optional<std::string> shard,
                  std::optional<std::string> csv, std::optional<std::string> json, std::optional<std::string> plot,
                  const py::object& plotSizeObject, bool quiet, py::object progress, std::optional<std::string> recordFile,
                  bool search, const py::object& maxEvals, const py::object& sceneTime, const py::object& animation) {
    requirePath(recordFile, "tradeoff: record");
    json = recordPath("tradeoff", json, recordFile);
    TradeoffStudyOptions s;
    applyRunArguments(s.run, scene, preset, settings);
    applyAnimationArguments(s.run, sceneTime, animation, "tradeoff");
    std::tie(s.run.width, s.run.height) = sizeArg(size, "tradeoff: size", limits::kSize, "tradeoff --size");
    s.knobs = knobs.value_or("");
    s.studies = studyList(studies);
    s.against = against;
    s.metric = metric;
    s.buffer = buffer;
    s.aoRays = intArg(aoRays, "tradeoff: ao_rays", limits::kAoRays, "tradeoff --ao-rays");
    s.refSpp = intArg(refSpp, "tradeoff: ref_spp", limits::kPixelSamples, "tradeoff --ref-spp");
    s.refFilter = refFilter;
    s.mask = mask.value_or("");
    s.time = time;
    s.cost = cost;
    s.budgetMs = optionalNumber(budgetMsObject, "tradeoff: budget_ms", "--budget-ms");
    s.budget = optionalNumber(budgetObject, "tradeoff: budget", "--budget");
    s.orbit = intArg(orbit, "tradeoff: orbit", OptionRange{0, limits::kOrbit.max}, "tradeoff --orbit; 0: fixed");
    s.orbitDegrees = optionalNumber(orbitDegrees, "tradeoff: orbit_degrees", "--orbit-degrees").value_or(360.0);
    s.walkthrough = walkthrough;
    s.frames = intArg(frames, "tradeoff: frames", limits::kFrames, "tradeoff --frames");
    s.warmup = intArg(warmup, "tradeoff: warmup", limits::kWarmup, "tradeoff --warmup");
    s.block = intArg(block, "tradeoff: block", limits::kBlock, "tradeoff --block");
    s.resamples = intArg(resamples, "tradeoff: resamples", limits::kResamples, "tradeoff --resamples");
    s.shard = shard.value_or("");
    s.search = search;
    if (!maxEvals.is_none() && !search) throw py::value_error("tradeoff: max_evals bounds search=True; give search=True with it");
    if (!maxEvals.is_none()) s.maxEvals = intArg(maxEvals, "tradeoff: max_evals", limits::kMaxEvals, "tradeoff --max-evals");
    const TradeoffFiles files{csv, json, plot,
                             sizeArg(plotSizeObject, "tradeoff: plot_size", limits::kPlotSize, "tradeoff --plot-size")};
    return tradeoffStudy(std::move(s), sweep, presets, exclude, files, quiet, progress);
}

}  // namespace

void bindTradeoff(py::module_& m) {
    m.def("tradeoff", &tradeoff, py::arg("scene") = "", py::arg("size") = std::make_pair(640, 360),
          py::arg("preset") = py::none(), py::arg("settings") = py::none(), py::arg("sweep") = py::none(),
          py::arg("presets") = py::none(), py::arg("knobs") = py::none(), py::arg("studies") = py::none(),
          py::arg("exclude") = py::none(),
          py::arg("against") = "reference", py::arg("metric") = "flip", py::arg("buffer") = "final",
          py::arg("ao_rays") = 64, py::arg("ref_spp") = 1, py::arg("ref_filter") = "box", py::arg("mask") = py::none(), py::arg("time") = "frame", py::arg("cost") = "gpu_ms",
          py::arg("budget_ms") = py::none(), py::arg("budget") = py::none(), py::arg("orbit") = 0,
          py::arg("orbit_degrees") = py::none(), py::arg("walkthrough") = false, py::arg("frames") = 5, py::arg("warmup") = 1, py::arg("block") = 1,
          py::arg("resamples") = 2000, py::arg("shard") = py::none(), py::arg("csv") = py::none(),
          py::arg("json") = py::none(), py::arg("plot") = py::none(), py::arg("plot_size") = std::make_pair(800, 600),
          py::arg("quiet") = false, py::arg("progress") = py::none(), py::arg("record") = py::none(),
          py::arg("search") = false, py::arg("max_evals") = py::none(), py::arg("scene_time") = py::none(),
          py::arg("animation") = py::none(),
          "tradeoff's sweep in this process: what each point costs in GPU ms and in error against the CPU reference\n"
          "(or against=\"knob=value,...\"), and the Pareto front. The keywords are tradeoff's options with their\n"
          "defaults (docs/tradeoffs.md): sweep={axis: [values]} (a knob, camera.near or camera.far; the full grid),\n"
          "presets=[...] (an axis), knobs=\"speed/quality\", studies=[{knob: value or [values]}, ...] or\n"
          "{name: {knob: ...}, ...} (several grids in one run, as repeated --study: the column study, one front),\n"
          "exclude=[\"axis=v,...\"], metric, buffer, ao_rays, ref_spp (the reference's samples per pixel, as reference\n"
          "--spp; default 1), ref_filter (\"box\" or \"tent\"), mask,\n"
          "time (frame, a pass, or a sum \"lighting+ao+ao_filter\"), cost (gpu_ms or a counter: fragments, samples,\n"
          "primitives, vertices, compute, bytes: the front's cost axis), budget_ms (bounds the time), budget (bounds\n"
          "the counter cost names, in its unit; not with budget_ms), orbit, orbit_degrees (the arc orbit's cameras span,\n"
          "default 360), walkthrough, frames, warmup, block,\n"
          "resamples, shard=\"i/n\"; settings={knob: value} as --set; scene_time (seconds) and animation (a clip's\n"
          "name or index, or \"none\") as --scene-time and --animation.\n"
          "Returns the experiment record tradeoff --json writes, as a dict, with two more keys: rows (the CSV's rows,\n"
          "a dict each: point, each axis, camera, metric, buffer, error, error_lo, error_hi, frames, frame_gpu_ms and\n"
          "its interval, gpu_ms.<pass>, the counters fragments, fragments.<pass>, ... bytes.<pass> when counted,\n"
          "pareto, time, time_ms and its interval, front (pareto|indistinguishable|dominated), dominated_by,\n"
          "tied_with [(point, axes)], pick, gpu_mem_peak_mib; NaN where the CSV is empty), front (the rows on the Pareto front of the\n"
          "point estimates) and front_rule (how dominance was decided); with budget_ms or budget, pick (point, row,\n"
          "tied, fitting, cheapest, lines: the least-error point whose time's 95% interval, or whose counter, ends\n"
          "under it). search=True (with budget_ms or budget; max_evals=N, default 48): instead of a grid, coordinate\n"
          "descent over the speed/quality knobs to the least error under the budget (tradeoff --search); rows are its\n"
          "evaluations, and search (found {knob: value}, evaluation, fits, evaluations, converged, grid_points, steps,\n"
          "lines) replaces pick; no plot is drawn.\n"
          "csv=, record= (or json=, its older name) and plot=PATH.png (plot_size=(w, h)) write tradeoff's files; only\n"
          "those asked for.\n"
          "Progress lines go to stderr (quiet=True: none) or to progress(line); Ctrl-C stops the run.\n"
          "A bad argument raises ValueError (KnobError for a knob) with the CLI's message, naming its flag.");
}

}  // namespace dw::python
