#pragma once
// The ranges of the numeric command-line options, in one place: the commands
// that parse the options (every subcommand), the Python module's keyword
// arguments (python/Arguments.h), the libraries that take the same values
// (renderer/metrics/Flip's pixels per degree, the reference's rays) and the
// experiment-record reader (a record is held to the limits of the options its
// fields stand for: renderer/record/ExperimentRecord) take them from here.
// Inclusive, unless a RealRange says its minimum is open.
//
// kNumericOptions below lists every numeric option of every subcommand with
// its range: headless/CommandLine reads a numeric option only through it (an
// option missing from the table is a programming error, std::logic_error),
// each command's --help prints its part, and tests/cli/OptionRangeCliTest
// walks it with out-of-range values.
#include <cmath>
#include <string_view>

namespace dw {

struct OptionRange {
    int min, max;
    bool holds(long long v) const { return v >= min && v <= max; }
};

// A range of real numbers; never holds NaN or an infinity.
struct RealRange {
    double min, max;
    bool minOpen = false;  // (min, max]: min itself is out
    bool holds(double v) const { return std::isfinite(v) && (minOpen ? v > min : v >= min) && v <= max; }
};

namespace limits {
constexpr OptionRange kSize{1, 16384};         // --size: width and height in pixels
constexpr OptionRange kPlotSize{50, 16384};    // bench/tradeoff --plot-size: the plot scripts' least, in pixels
constexpr OptionRange kFrames{1, 100000};      // --frames: counted frames
constexpr OptionRange kGuiFrames{0, 1000000};  // gui --frames: frames before the window closes (0: until closed)
constexpr OptionRange kCompareFrames{1, 1000}; // compare --frames: frames each side renders
constexpr OptionRange kWarmup{0, 100000};      // --warmup: frames left out of the timings
constexpr OptionRange kBlock{1, 100000};       // bench/tradeoff --block
constexpr OptionRange kResamples{100, 1000000};  // bench/tradeoff --resamples
constexpr OptionRange kBenchLights{0, 1000000};  // bench --lights, each count
constexpr OptionRange kOrbit{1, 100000};       // bench/tradeoff --orbit poses
constexpr OptionRange kShards{1, 100000};      // bench/tradeoff --shard i/n: n
constexpr OptionRange kLppPoses{1, 1000};      // bench --lpp-poses, list --poses
constexpr OptionRange kAoRays{1, 1 << 20};     // reference/compare/tradeoff --ao-rays
constexpr OptionRange kSeed{0, 2147483647};    // reference/bench --seed
constexpr OptionRange kPixelSamples{1, 65536}; // reference --spp (tradeoff --ref-spp): samples per pixel
constexpr OptionRange kReferenceThreads{0, 4096};  // reference --threads (0: every core)
constexpr OptionRange kMaxEvals{1, 100000};    // tradeoff --max-evals: the search's evaluations
// The largest finite 32-bit float: no difference of two float images, and no
// light radius a 32-bit light table holds, is larger.
constexpr double kFloatMax = 3.4028234663852886e38;
constexpr RealRange kThreshold{0, kFloatMax};      // compare --fail/--warn/--hardfail/--hardwarn: |reference - test|
constexpr RealRange kPercent{0, 100};              // compare --failpercent/--warnpercent: % of the pixels
constexpr RealRange kFlipGate{0, 1};               // compare --fail-flip: mean FLIP
constexpr RealRange kSsimGate{-1, 1};              // compare --fail-ssim: mean SSIM
// FLIP's pixels per degree: the filters' radius grows with it (ppd 1000 is a
// 271-tap filter; past it the radius overflows, or the run takes minutes).
constexpr RealRange kPixelsPerDegree{1, 1000};
constexpr RealRange kLightRadius{0, kFloatMax, true};  // bench --light-radius: world units, above 0
constexpr RealRange kBudgetMs{0, 1e9, true};            // tradeoff --budget-ms: milliseconds, above 0
constexpr RealRange kBudget{0, 1e18, true};             // tradeoff --budget: a counter's unit (fragments, bytes ...), above 0
constexpr RealRange kSceneTime{0, 1e6};                 // --scene-time: seconds of the scene's animation
constexpr RealRange kOrbitDegrees{0, 360, true};        // tradeoff --orbit-degrees: the arc the poses span, above 0
constexpr RealRange kFrameRate{0, 1e4, true};           // render --frame-rate: frames per second of scene time, above 0
}  // namespace limits

// How an option's value is written.
enum class OptionForm {
    Whole,      // one whole number
    WholeList,  // a comma list of whole numbers (bench --lights)
    Real,       // one real number (finite)
    Size,       // WIDTHxHEIGHT, each in the range
    SizeList,   // a comma list of sizes (bench --size)
    Shard,      // i/n: n in the range, 0 <= i < n
};

struct NumericOption {
    std::string_view command;  // "render", "bench merge", ...
    std::string_view flag;     // "--frames"
    OptionForm form;
    double min, max;
    bool minOpen = false;
    std::string_view what;  // the unit or meaning, for the messages and the help

    constexpr NumericOption(std::string_view c, std::string_view f, OptionForm form_, OptionRange r, std::string_view w)
        : command(c), flag(f), form(form_), min(r.min), max(r.max), what(w) {}
    constexpr NumericOption(std::string_view c, std::string_view f, RealRange r, std::string_view w)
        : command(c), flag(f), form(OptionForm::Real), min(r.min), max(r.max), minOpen(r.minOpen), what(w) {}
    bool whole() const { return form != OptionForm::Real; }
    bool holds(double v) const { return std::isfinite(v) && (minOpen ? v > min : v >= min) && v <= max; }
};

namespace limits {
using F = OptionForm;
// Every numeric option of every subcommand, in the order its --help names them.
inline constexpr NumericOption kNumericOptions[] = {
    {"gui", "--size", F::Size, kSize, "window pixels"},
    {"gui", "--frames", F::Whole, kGuiFrames, "frames, 0: until closed"},
    {"render", "--size", F::Size, kSize, "pixels"},
    {"render", "--frames", F::Whole, kFrames, "counted frames"},
    {"render", "--scene-time", kSceneTime, "seconds of the scene's animation"},
    {"render", "--orbit", F::Whole, kOrbit, "cameras"},
    {"render", "--orbit-degrees", kOrbitDegrees, "degrees the orbit's poses span"},
    {"render", "--time-steps", F::Whole, kOrbit, "frames over scene time"},
    {"render", "--frame-rate", kFrameRate, "frames per second of scene time"},
    {"render", "--warmup", F::Whole, kWarmup, "frames"},
    {"render", "--ao-rays", F::Whole, kAoRays, "AO rays per pixel"},
    {"render", "--seed", F::Whole, kSeed, "seed"},
    {"render", "--spp", F::Whole, kPixelSamples, "samples per pixel"},
    {"render", "--threads", F::Whole, kReferenceThreads, "threads, 0: every core"},
    {"bench", "--size", F::SizeList, kSize, "pixels"},
    {"bench", "--lights", F::WholeList, kBenchLights, "lights"},
    {"bench", "--frames", F::Whole, kFrames, "counted frames"},
    {"bench", "--scene-time", kSceneTime, "seconds of the scene's animation"},
    {"bench", "--warmup", F::Whole, kWarmup, "frames"},
    {"bench", "--block", F::Whole, kBlock, "frames in a row"},
    {"bench", "--resamples", F::Whole, kResamples, "bootstrap resamples"},
    {"bench", "--orbit", F::Whole, kOrbit, "cameras"},
    {"bench", "--shard", F::Shard, kShards, "shards"},
    {"bench", "--seed", F::Whole, kSeed, "seed"},
    {"bench", "--light-radius", kLightRadius, "world units"},
    {"bench", "--lpp-poses", F::Whole, kLppPoses, "camera poses"},
    {"bench", "--plot-size", F::Size, kPlotSize, "pixels"},
    {"bench merge", "--resamples", F::Whole, kResamples, "bootstrap resamples"},
    {"bench merge", "--plot-size", F::Size, kPlotSize, "pixels"},
    {"reference", "--size", F::Size, kSize, "pixels"},
    {"reference", "--scene-time", kSceneTime, "seconds of the scene's animation"},
    {"reference", "--ao-rays", F::Whole, kAoRays, "AO rays per pixel"},
    {"reference", "--seed", F::Whole, kSeed, "seed"},
    {"reference", "--spp", F::Whole, kPixelSamples, "samples per pixel"},
    {"reference", "--threads", F::Whole, kReferenceThreads, "threads, 0: every core"},
    {"tradeoff", "--size", F::Size, kSize, "pixels"},
    {"tradeoff", "--frames", F::Whole, kFrames, "counted frames"},
    {"tradeoff", "--scene-time", kSceneTime, "seconds of the scene's animation"},
    {"tradeoff", "--warmup", F::Whole, kWarmup, "frames"},
    {"tradeoff", "--block", F::Whole, kBlock, "frames in a row"},
    {"tradeoff", "--resamples", F::Whole, kResamples, "bootstrap resamples"},
    {"tradeoff", "--orbit", F::Whole, kOrbit, "cameras"},
    {"tradeoff", "--orbit-degrees", kOrbitDegrees, "degrees the orbit's poses span"},
    {"tradeoff", "--shard", F::Shard, kShards, "shards"},
    {"tradeoff", "--ao-rays", F::Whole, kAoRays, "AO rays per pixel"},
    {"tradeoff", "--ref-spp", F::Whole, kPixelSamples, "samples per pixel"},
    {"tradeoff", "--plot-size", F::Size, kPlotSize, "pixels"},
    {"tradeoff", "--budget-ms", kBudgetMs, "GPU milliseconds"},
    {"tradeoff", "--budget", kBudget, "the --cost counter's unit"},
    {"tradeoff", "--max-evals", F::Whole, kMaxEvals, "evaluations"},
    {"tradeoff merge", "--plot-size", F::Size, kPlotSize, "pixels"},
    {"tradeoff merge", "--budget-ms", kBudgetMs, "GPU milliseconds"},
    {"tradeoff merge", "--budget", kBudget, "the --cost counter's unit"},
    {"compare", "--size", F::Size, kSize, "pixels"},
    {"compare", "--frames", F::Whole, kCompareFrames, "frames"},
    {"compare", "--ao-rays", F::Whole, kAoRays, "AO rays per pixel"},
    {"compare", "--fail", kThreshold, "|difference|"},
    {"compare", "--warn", kThreshold, "|difference|"},
    {"compare", "--failpercent", kPercent, "% of the pixels"},
    {"compare", "--warnpercent", kPercent, "% of the pixels"},
    {"compare", "--hardfail", kThreshold, "|difference|"},
    {"compare", "--hardwarn", kThreshold, "|difference|"},
    {"compare", "--fail-flip", kFlipGate, "mean FLIP"},
    {"compare", "--fail-ssim", kSsimGate, "mean SSIM"},
    {"compare", "--ppd", kPixelsPerDegree, "pixels per degree"},
    {"list", "--size", F::Size, kSize, "pixels"},
    {"list", "--poses", F::Whole, kLppPoses, "camera poses (list scenes --stats)"},
};
}  // namespace limits

// The table's entry for `flag` of `command`; nullptr when it has none.
constexpr const NumericOption* findNumericOption(std::string_view command, std::string_view flag) {
    for (const NumericOption& o : limits::kNumericOptions)
        if (o.command == command && o.flag == flag) return &o;
    return nullptr;
}

}  // namespace dw
