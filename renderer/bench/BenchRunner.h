#pragma once
// Runs a `bench` grid in one process and one GL context (seed 000 chapter 6's
// measurements, made repeatable): one RenderSession per render size (so a
// size change is a switch of framebuffers, not a reallocation), the scene
// loaded once, and for each light count a list of generated lights kept
// ready, so a configuration switch is swapping the session's light list (the
// light table is rebuilt from it every frame; the geometry stays uploaded)
// and re-applying the knobs in the run configuration's order plus the
// configuration's own values. The timed rounds are ConfigurationRunner's
// (shared with tradeoff): interleaved, round after round every configuration
// renders its warm-up frames (left out) and then a block of counted frames,
// so slow drift of the machine falls on all of them alike; PassTimer's
// timestamps are harvested without waiting inside the loop and streamed to
// the caller as they come. Lights per pixel come first, from an extra,
// untimed frame per configuration that asks for lighting.overlap (the
// counting variant costs more than plain shading).
#include <cstdint>
#include <functional>
#include <set>
#include <utility>
#include <string>

#include "renderer/RunConfig.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/bench/BenchResults.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/bench/GridExclusion.h"
#include "renderer/scene/Scene.h"

namespace dw {

class CameraPath;
class ConfigurationRunner;

struct BenchOptions {
    RunConfig run;     // scene, preset, --set: every configuration starts from them
    BenchGrid grid;    // sizes, light counts, knob axes
    int frames = 10;   // counted frames per configuration
    int warmup = 1;    // frames left out after each switch to a configuration
    int block = 1;     // counted frames per configuration in a row
    std::uint32_t seed = 1;
    float lightRadius = 0.0f;       // <= 0: a tenth of the scene bounds' diagonal
    bool keepSceneLights = false;   // generated lights are added to the scene's instead of replacing them
    int orbit = 0;                  // > 0: the camera orbits through this many poses
    bool walkthrough = false;       // the camera follows the scene's camera.path
    int lppPoses = 4;               // poses the LPP frame is averaged over on a moving camera
    bool lpp = true;
    bool counters = true;  // each pass's cost counters (PassCounts.h) in the samples (--no-counters: off)
    BenchShard shard;
    GridExclusion exclude;  // --exclude: corners of the grid left out (axes size, lights and the knobs)
    std::string baseline;  // --baseline axis=value; empty: chooseBaseline's rule
};

using BenchProgress = std::function<void(const std::string&)>;
// Called as the timed rounds go with the frames just harvested (whole
// frames, their rows in pipeline order); `so far` holds the run's knob axes
// and configurations with their LPP, to write the samples CSV's rows from
// (BenchResults::csvRows). So a killed run keeps what it measured.
using BenchStream = std::function<void(const BenchResults& soFar, const std::vector<BenchSample>& fresh)>;

class BenchRunner {
public:
    // Checks the options and every knob value against the declarations and
    // loads the scene: everything that can fail without GL fails here.
    explicit BenchRunner(BenchOptions options);

    const std::vector<BenchConfig>& configs() const { return configs_; }  // this shard's
    size_t gridSize() const { return gridSize_; }
    // What each ratio divides by, chosen over the whole grid (a shard runs
    // whole comparison groups along its axis, so it has every baseline it needs).
    const BenchBaseline& baseline() const { return baseline_; }
    float lightRadius() const { return radius_; }
    const Scene& scene() const { return scene_; }

    // Needs a current GL 4.5 context. `progress` gets a line now and then.
    // Lights per pixel are measured first (untimed), then the timed rounds.
    // `resumed`: the samples of an earlier, interrupted run of this grid
    // (bench --resume): its counted frames with a "frame" row are kept and
    // not measured again (a frame cut short is measured again); the new
    // frames' seq continue after its. Throws Error when it is another grid.
    BenchResults run(const BenchProgress& progress = {}, const BenchStream& stream = {},
                     const BenchResults* resumed = nullptr);
    // Where run() sends its warnings, one line each: AOV's cost (a
    // configuration over AovCostEstimate's limits, before any frame) and what
    // the passes lost in a configuration's counted frames (FrameWarnings: the
    // oit pass's fragments). stderr when unset (the CLI); the Python module
    // turns them into warnings.warn.
    void setWarningSink(std::function<void(const std::string&)> sink) { warning_ = std::move(sink); }

private:
    // run()'s stages (BenchRunner.cpp).
    void timeRounds(ConfigurationRunner& runner, BenchResults& results, const std::set<std::pair<int, int>>& measured,
                    long long seqBase, const BenchStream& stream, const BenchProgress& say) const;
    BenchFields settingsOf(const CameraPath& path, double seconds) const;
    void warn(const std::string& line) const;

    std::function<void(const std::string&)> warning_;
    BenchOptions o_;
    Scene scene_;
    std::vector<BenchConfig> configs_;
    size_t gridSize_ = 0;
    BenchBaseline baseline_;
    float radius_ = 0.0f;
    double threshold_ = 0.0;
};

}  // namespace dw
