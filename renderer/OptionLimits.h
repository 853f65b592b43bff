#pragma once
// The ranges of the numeric command-line options, in one place: the commands
// that parse the options (render, bench, tradeoff, reference), the Python
// module's keyword arguments (python/Module.cpp) and the experiment-record
// reader (a record is held to the limits of the options its fields stand
// for: renderer/record/ExperimentRecord) take them from here. Inclusive.
namespace dw {

struct OptionRange {
    int min, max;
    bool holds(long long v) const { return v >= min && v <= max; }
};

namespace limits {
constexpr OptionRange kSize{1, 16384};         // --size: width and height in pixels
constexpr OptionRange kFrames{1, 100000};      // --frames: counted frames
constexpr OptionRange kWarmup{0, 100000};      // --warmup: frames left out of the timings
constexpr OptionRange kBlock{1, 100000};       // bench/tradeoff --block
constexpr OptionRange kResamples{100, 1000000};  // bench/tradeoff --resamples
constexpr OptionRange kBenchLights{0, 1000000};  // bench --lights, each count
constexpr OptionRange kOrbit{1, 100000};       // bench/tradeoff --orbit poses
constexpr OptionRange kLppPoses{1, 1000};      // bench --lpp-poses
constexpr OptionRange kAoRays{1, 1 << 20};     // reference/compare/tradeoff --ao-rays
constexpr OptionRange kSeed{0, 2147483647};    // reference/bench --seed
constexpr OptionRange kReferenceThreads{0, 4096};  // reference --threads (0: every core)
}  // namespace limits

}  // namespace dw
