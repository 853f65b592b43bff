#pragma once
// One `tradeoff` study from the options the CLI and the Python module take
// (deferred_workbench.tradeoff): the options checked once for both, the
// sweep about the current settings for --knobs speed/quality, and the
// measurement: the TradeoffRunner's timed rounds and errors, with the CPU
// references through the shared cache (each distinct one rendered once in
// the run), and the machine fields and record a run writes.
// Used by `tradeoff`, `replay` of a tradeoff record and the Python module.
// Only measure() needs GL: a current 4.5 context, the caller's (the CLI's
// HeadlessGlContext, the module's process context).
// Follows issue 23 (tradeoff) and issue 24 (records, Python).
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/RunConfig.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/study/CachedReferences.h"
#include "renderer/study/TradeoffStudies.h"

namespace dw {

// The options as the CLI's flags give them (docs/tradeoffs.md says each one;
// the Python keywords are the same names with '_' for '-').
struct TradeoffStudyOptions {
    RunConfig run;                       // scene, preset, --set; width x height (the CLI's default 640x360)
    std::vector<BenchKnobAxis> sweep;    // each as --sweep reads it (BenchGrid::parseSweep): axis=v1,v2,...
    std::vector<std::string> presets;    // --presets: presets as an axis (the column 'preset', first)
    std::string knobs;                   // "" or "speed/quality" (--knobs)
    // --study / --study-file: several grids in one run (TradeoffStudies), not with --sweep, --presets or --knobs.
    std::vector<TradeoffStudySpec> studies;
    std::vector<std::string> exclude;    // each as --exclude takes it: axis=v[,v...][,axis=v...]
    std::string against = "reference";   // or knob=value[,knob=value...]
    std::string metric = "flip";         // flip | rms | psnr | ssim
    std::string buffer = "final";        // final | lbuffer | ao | shadow
    std::string mask;                    // "" or shadow_edges
    std::string time = "frame";          // frame, a pass's name, or a sum of them (a+b+c)
    std::optional<double> budgetMs;      // --budget-ms: picks by time (BudgetPicker); must be finite and above 0
    std::optional<double> budget;        // --budget: picks by the counter --cost names, in its unit; finite, above 0
    std::string cost = "gpu_ms";         // the front's cost axis: gpu_ms or a counter (TradeoffTable::costOf)
    bool counters = true;                // count each pass's cost counters (--no-counters: off)
    int aoRays = 64;                     // the reference's AO rays per pixel, 1 .. 2^20
    int refSpp = 1;                      // --ref-spp: the reference's samples per pixel, 1 .. 65536 (reference --spp)
    std::string refFilter = "box";       // --ref-filter: box | tent (reference --filter)
    int orbit = 0;                       // 0: the run's camera; 1 .. 100000 cameras on an orbit
    double orbitDegrees = 360;           // the arc the orbit's cameras span (0, 360]
    bool walkthrough = false;            // the scene's camera.path keyframes
    int frames = 5, warmup = 1, block = 1, resamples = 2000;
    std::string shard;                   // "" (the whole sweep) or i/n
    bool search = false;                 // --search: walk the speed/quality knobs (BudgetSearch), needs a budget
    int maxEvals = 48;                   // --max-evals: the search's bound, 1 .. 100000
};

// What measure() reports while it runs, and how a caller stops it.
struct TradeoffStudyProgress {
    std::function<void(const std::string&)> line;     // a progress line ("tradeoff: ...")
    std::function<void(const std::string&)> warning;  // a note or warning ("note: ...", "warning: ...")
    // Asked before each progress line and each reference: true stops the run
    // (TradeoffCancelled) with nothing written.
    std::function<bool()> cancelled;
};

// A run stopped by TradeoffStudyProgress::cancelled. Not a dw::Error, so no
// per-point error handling swallows it.
class TradeoffCancelled : public std::runtime_error {
public:
    TradeoffCancelled() : std::runtime_error("tradeoff: cancelled") {}
};

struct TradeoffMeasurement {
    TradeoffResult result;
    BenchFields machine;  // the GL strings and platform, cpu, compiler, date
};

class TradeoffStudy {
public:
    // Checks every option that needs no scene and no GL, in the CLI's order
    // and with its messages (they name the CLI's flags): the size (1 ..
    // 16384), each --sweep, --presets, --knobs (only speed/quality, and not
    // with axes), each --exclude, --against, the counts' ranges, --shard, and
    // that there are axes. Throws dw::Error (the CLI's usage errors).
    // The knobs, presets' names, metric, buffer, mask and scene are checked
    // by the TradeoffRunner made from the result.
    static TradeoffOptions check(const TradeoffStudyOptions& options);

    // --ref-spp and --ref-filter as the references take them. Throws Error
    // (--ref-spp outside 1 .. 65536, a filter other than box or tent).
    static ReferencePixels referencePixels(const TradeoffStudyOptions& options);

    // check(), then with --knobs speed/quality the sweep about the current
    // settings (the run's knobs on its scene, which is loaded: FileError /
    // Error for a bad one), or with studies their listed sweep
    // (TradeoffStudies::sweep: TradeoffStudyError for a bad one), keeping the exclusions.
    static TradeoffOptions runnerOptions(const TradeoffStudyOptions& options);

    // The runner's sweep with the references through the shared cache
    // (ReferenceCache: each distinct one rendered once in this run, with
    // `aoRays` AO rays per pixel, their pattern seeded by `referenceSeed`, as
    // reference --seed; a record holds it as seeds.reference; `pixels` samples
    // per pixel and their filter, as reference --spp and --filter). Needs a current
    // GL 4.5 context, whose EGL platform is `glPlatform`. Throws
    // TradeoffCancelled when asked to stop.
    static TradeoffMeasurement measure(TradeoffRunner& runner, int aoRays, const std::string& glPlatform,
                                       const TradeoffStudyProgress& progress = {}, std::uint32_t referenceSeed = 1,
                                       ReferencePixels pixels = {});

    // The experiment record tradeoff --json writes (replay runs it again):
    // `given` the options the runner was made from; `command` goes into its settings.
    static ExperimentRecord record(const TradeoffStudyOptions& options, const TradeoffOptions& given,
                                   const TradeoffRunner& runner, TradeoffMeasurement measured,
                                   const std::string& command);
};

}  // namespace dw
