#include "renderer/study/TradeoffStudy.h"

#include "renderer/bench/BudgetPick.h"

#include <cstdio>
#include <map>
#include <optional>

#include "renderer/Error.h"
#include "renderer/OptionLimits.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/record/HostInfo.h"
#include "renderer/study/BudgetSearch.h"
#include "renderer/study/CachedReferences.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

// As CommandLine::parseInt says a number out of its range.
int inRange(const std::string& flag, int v, OptionRange range) {
    if (!range.holds(v))
        throw Error(flag + " must be between " + std::to_string(range.min) + " and " + std::to_string(range.max));
    return v;
}

// --budget-ms bounds the measured time, --budget the counter --cost names:
// one of them, each finite and above 0 (one line, before anything renders).
void checkBudgets(const TradeoffStudyOptions& s, TradeoffOptions& o) {
    if (s.budgetMs && s.budget)
        throw Error("--budget-ms and --budget: give one (--budget-ms bounds the measured time in ms, --budget the "
                    "counter --cost names in its own unit)");
    if (s.budget && (s.cost == "gpu_ms"))
        throw Error("--budget bounds a counter: give --cost fragments|samples|primitives|vertices|compute|bytes "
                    "(for time, --budget-ms)");
    if (s.budgetMs) BudgetPicker::check(*s.budgetMs);  // 0, negative, NaN, inf
    if (s.budget) BudgetPicker::check(*s.budget, "--budget");
    o.budgetMs = s.budgetMs.value_or(0.0);
    o.budget = s.budget.value_or(0.0);
}

// --study makes its own grids: alone (not with --sweep, --presets or
// --knobs), each study checked and named (TradeoffStudies::named).
void checkStudies(const TradeoffStudyOptions& s) {
    for (const BenchKnobAxis& axis : s.sweep)
        if (TradeoffSweep::isStudyAxis(axis.knob))
            throw TradeoffStudyError("--sweep study: 'study' names each point's study (give --study KNOB=V1,V2,...)");
    if (s.studies.empty()) return;
    if (!s.sweep.empty() || !s.presets.empty() || !s.knobs.empty())
        throw TradeoffStudyError("--study makes its own grids: give it without --sweep, --presets or --knobs (a "
                                 "--sweep's knob goes into each --study)");
    (void)TradeoffStudies::named(s.studies);
}

// --search walks the speed/quality knobs itself (BudgetSearch): it needs a
// budget and takes no other axes; its knobs are --knobs speed/quality's.
TradeoffStudyOptions withSearch(TradeoffStudyOptions s) {
    if (!s.search) return s;
    if (!s.sweep.empty() || !s.presets.empty() || !s.studies.empty())
        throw Error("--search walks the speed/quality knobs itself: give it without --sweep, --presets or --study");
    if (!s.budgetMs && !s.budget)
        throw Error("--search needs a budget: --budget-ms X (or --budget N with --cost fragments|...)");
    if (!s.exclude.empty()) throw Error("--search takes no --exclude (it walks every speed/quality knob)");
    if (!s.shard.empty()) throw Error("--search cannot be sharded: each step depends on the one before");
    BudgetSearch::checkMaxEvals(s.maxEvals);
    if (s.knobs.empty()) s.knobs = "speed/quality";
    return s;
}

}  // namespace

TradeoffOptions TradeoffStudy::check(const TradeoffStudyOptions& given) {
    const TradeoffStudyOptions s = withSearch(given);
    TradeoffOptions o;
    o.run = s.run;
    inRange("--size width", s.run.width, limits::kSize);
    inRange("--size height", s.run.height, limits::kSize);
    for (const BenchKnobAxis& axis : s.sweep) {
        BenchGrid::checkAxis(axis);
        for (const auto& a : o.sweep.axes)
            if (a.name == axis.knob) throw Error("--sweep " + axis.knob + " is given twice");
        o.sweep.axes.push_back({axis.knob, axis.values});
    }
    if (!s.presets.empty()) {
        for (const auto& p : s.presets)
            if (p.empty()) throw Error("--presets: an empty preset name");
        o.sweep.axes.insert(o.sweep.axes.begin(), TradeoffAxis{"preset", s.presets});
    }
    if (!s.knobs.empty() && s.knobs != "speed/quality")
        throw Error("--knobs: the only set is speed/quality (the knobs marked as trading speed for quality), got '" +
                    s.knobs + "'");
    if (!s.knobs.empty() && !o.sweep.axes.empty())
        throw Error("--knobs speed/quality sweeps its own axes; give it without --sweep or --presets");
    checkStudies(s);
    for (const auto& e : s.exclude) o.sweep.exclusion.add(e);
    if (s.against != "reference") o.against = splitList(s.against, "--against");
    o.metric = s.metric;
    o.buffer = s.buffer;
    o.mask = s.mask;
    o.time = s.time;
    if (!TradeoffTable::isCost(s.cost))
        throw Error("--cost: expected one of " + TradeoffTable::costNames() + ", got '" + s.cost + "'");
    if (s.cost != "gpu_ms" && !s.counters) throw Error("--cost " + s.cost + " needs the counters: drop --no-counters");
    o.cost = s.cost;
    o.counters = s.counters;
    checkBudgets(s, o);
    inRange("--ao-rays", s.aoRays, limits::kAoRays);
    (void)referencePixels(s);
    if (s.orbit != 0) o.orbit = inRange("--orbit", s.orbit, limits::kOrbit);
    if (!limits::kOrbitDegrees.holds(s.orbitDegrees))
        throw Error("--orbit-degrees: expected more than 0 and at most 360 degrees, got " + std::to_string(s.orbitDegrees));
    o.orbitDegrees = s.orbitDegrees;
    if (s.orbitDegrees != 360.0 && s.orbit == 0) throw Error("--orbit-degrees is the arc of --orbit N's cameras; give --orbit");
    if (s.metric == "temporal" && s.orbit < 2 && !s.walkthrough)
        throw Error("--metric temporal measures the change from frame to frame along a camera path: give --orbit N "
                    "(N >= 2) or --walkthrough (a camera.path of 2 or more keyframes)");
    o.walkthrough = s.walkthrough;
    o.frames = inRange("--frames", s.frames, limits::kFrames);
    o.warmup = inRange("--warmup", s.warmup, limits::kWarmup);
    o.block = inRange("--block", s.block, limits::kBlock);
    o.resamples = inRange("--resamples", s.resamples, limits::kResamples);
    if (!s.shard.empty()) o.shard = BenchShard::parse(s.shard);
    if (o.sweep.axes.empty() && s.knobs.empty() && s.studies.empty())
        throw Error("tradeoff needs axes: --sweep knob=v1,v2,..., --presets A,B,..., --knobs speed/quality or "
                    "--study KNOB=V1,V2[:KNOB=V...]");
    return o;
}

ReferencePixels TradeoffStudy::referencePixels(const TradeoffStudyOptions& s) {
    ReferencePixels p;
    p.samples = inRange("--ref-spp", s.refSpp, limits::kPixelSamples);
    if (s.refFilter != "box" && s.refFilter != "tent")
        throw Error("--ref-filter: expected box or tent, got '" + s.refFilter + "'");
    p.filter = reference::pixelFilterNamed(s.refFilter);
    return p;
}

TradeoffOptions TradeoffStudy::runnerOptions(const TradeoffStudyOptions& given) {
    const TradeoffStudyOptions s = withSearch(given);
    TradeoffOptions o = check(s);
    if (!s.knobs.empty() || !s.studies.empty()) {
        // About the current settings: the run configuration's knobs on its scene.
        o.run.validate();
        const Scene scene = loadScene(o.run.sceneSpec());
        KnobRegistry current = RunConfig::declaredKnobs();
        o.run.applyKnobs(current, scene);
        GridExclusion exclusion = o.sweep.exclusion;
        o.sweep = s.studies.empty() ? TradeoffSweep::aroundCurrent(current)
                                    : TradeoffStudies::sweep(TradeoffStudies::named(s.studies), current);
        o.sweep.exclusion = exclusion;
    }
    return o;
}

TradeoffMeasurement TradeoffStudy::measure(TradeoffRunner& runner, int aoRays, const std::string& glPlatform,
                                           const TradeoffStudyProgress& progress, std::uint32_t referenceSeed,
                                           ReferencePixels pixels) {
    auto stopIfAsked = [&] {
        if (progress.cancelled && progress.cancelled()) throw TradeoffCancelled();
    };
    auto say = [&](const std::string& line) {
        stopIfAsked();
        if (progress.line) progress.line(line);
    };
    auto warn = [&](const std::string& line) {
        if (progress.warning) progress.warning(line);
    };
    // References through the shared cache; each distinct one rendered once in this run.
    CachedReferences references(aoRays, referenceSeed, {say, warn, stopIfAsked}, pixels);
    const TradeoffReference reference = references.function();

    TradeoffMeasurement m;
    if (progress.warning) runner.setWarningSink(progress.warning);
    m.result = runner.run(reference, say);
    TradeoffResult& result = m.result;
    BenchFields& machine = m.machine;
    machine = result.machine;
    machine.emplace_back("gl_platform", glPlatform);
    machine.emplace_back("cpu", cpuModel());
    machine.emplace_back("compiler", compilerName());
    machine.emplace_back("date", utcNow());
    if (runner.options().against.empty()) {
        result.settings.emplace_back("references_rendered", std::to_string(references.rendered()));
        result.settings.emplace_back("references_from_cache", std::to_string(references.fromCache()));
        char text[32];
        std::snprintf(text, sizeof(text), "%.6g", references.seconds());
        result.settings.emplace_back("reference_seconds", text);
    }
    return m;
}

ExperimentRecord TradeoffStudy::record(const TradeoffStudyOptions& options, const TradeoffOptions& given,
                                       const TradeoffRunner& runner, TradeoffMeasurement measured,
                                       const std::string& command) {
    measured.result.settings.emplace_back("command", command);
    RecordedTradeoff recorded;
    recorded.options = given;
    recorded.exclude = options.exclude;
    recorded.aoRays = options.aoRays;
    recorded.refSpp = options.refSpp;
    recorded.refFilter = options.refFilter;
    recorded.runPreset = options.run.presetSpec();
    recorded.runPresets = options.run.presetSpecs();
    recorded.runSets = options.run.sets;
    recorded.search = options.search;
    recorded.maxEvals = options.search ? options.maxEvals : 0;
    return ExperimentRecord::forTradeoff(recorded, runner.scene(), measured.result, measured.machine);
}

}  // namespace dw
