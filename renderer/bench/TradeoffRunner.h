#pragma once
// Runs a `tradeoff` sweep in one process and one GL context: at each point
// of the sweep (TradeoffSweep) and each camera, what it costs and how far it
// lands from what it is measured against.
// Reads: the run configuration (scene, preset, --set, size), the sweep, the
// cameras (the run's camera; --orbit N poses about it; or each keyframe of
// the scene's camera.path). Writes: a TradeoffTable, one row per point and
// camera (and an "all" row per point when there are several cameras).
//   Time: the shared ConfigurationRunner over (point, camera) configurations,
//     interleaved, with warm-up: the median GPU ms per frame (bootstrap 95%
//     interval of the median) and per pass.
//   Error: an untimed frame of each (point, camera), its buffer (--buffer:
//     final, lbuffer, or ao = the AO buffer the lighting pass reads) against
//     the reference's same buffer (TradeoffReference: the caller's CPU ground
//     truth through its cache) or against the point with --against's knob
//     values on top, rendered here once per distinct configuration and camera.
//     ImageError: the metric with a tile-bootstrap interval; the "all" row
//     the mean over cameras with a bootstrap over the cameras.
//   Front: ConfidentFront's paired bootstrap (TradeoffEvidence: the rounds
//     and the tiles resampled alike for every point); with a budget, the pick.
// Follows issue 23 ("the speed/accuracy lab").
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "renderer/RunConfig.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/bench/BenchResults.h"
#include "renderer/bench/BenchRunner.h"
#include "renderer/bench/BudgetPick.h"
#include "renderer/bench/ImageError.h"
#include "renderer/bench/TradeoffSweep.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/gl/CompiledShaders.h"
#include "renderer/io/ImageIO.h"
#include "renderer/knobs/KnobAssignment.h"
#include "renderer/scene/Camera.h"
#include "renderer/scene/Scene.h"

namespace dw {

class ConfigurationRunner;
class RenderSession;
struct RunnerTimings;

struct TradeoffOptions {
    RunConfig run;  // scene, preset, --set, width x height
    TradeoffSweep sweep;
    int frames = 5, warmup = 1, block = 1;
    int orbit = 0;             // > 0: this many cameras on an orbit about the run's camera
    double orbitDegrees = 360;  // the arc the orbit's cameras span, orbitDegrees / orbit apart (CameraPath::orbit)
    bool walkthrough = false;  // the scene's camera.path keyframes as the cameras
    // rms, flip, psnr, ssim (ImageError), or temporal: the temporal error
    // (renderer/metrics/TemporalError.h) of the path's frames rendered in order,
    // on the "all" row (a camera's row has none); needs --orbit N >= 2 or --walkthrough.
    std::string metric = "rms";
    std::string buffer = "final";
    // "" or "shadow_edges": the error over the pixels within 2 px of an edge of
    // the reference's shadow buffer only (ShadowEdgeMask, MaskedMetrics); the
    // rows' buffer reads "<buffer>:shadow_edges".
    std::string mask;
    // What the front ranks by: "frame", a pass's or span's gpu_ms, or a sum of
    // them ("lighting+ao+ao_filter": per frame, the terms' sum; TradeoffTable::timeTerms).
    std::string time = "frame";
    double budgetMs = 0.0;  // > 0: pick the least-error point whose time is under it (BudgetPicker); 0: none
    double budget = 0.0;    // > 0: pick the least-error point whose counter `cost` is under it, in its unit; 0: none
    std::string cost = "gpu_ms";  // the front's cost axis: gpu_ms or a counter (TradeoffTable::costOf)
    bool counters = true;         // count each pass's cost counters (PassCounts.h) in the timed frames
    std::vector<std::string> against;  // empty: the reference; else knob=value on top of each point
    int resamples = 2000;
    BenchShard shard;  // points whose number % count == index
};

// The reference image of `buffer` ("final", "lbuffer", "ao", "shadow") for `camera`
// at width x height, under the point's knobs (which the reference model reads).
using TradeoffReference = std::function<FloatImage(const Scene& scene, const KnobRegistry& knobs, const Camera& camera,
                                                   int width, int height, const std::string& buffer)>;

struct TradeoffResult {
    TradeoffTable table;
    BenchFields machine;   // the GL strings
    BenchFields settings;  // scene, size, frames, cameras, metric, buffer, against, seconds ...
    double timingSeconds = 0.0, errorSeconds = 0.0;  // the timed rounds; the captures and errors (references included)
    gl::CompiledShaders shaders;  // the shader files the run compiled (the record hashes them)
    BudgetPick pick;              // with TradeoffOptions::budgetMs or budget: what it picked (lines empty without)
};

class TradeoffRunner {
public:
    // Checks every axis value (knobs against their declarations, presets,
    // clip planes), --against, the metric and the buffer, and loads the
    // scene: everything that can fail without GL fails here.
    explicit TradeoffRunner(TradeoffOptions options);

    const std::vector<TradeoffPoint>& points() const { return points_; }  // this shard's
    size_t sweepSize() const { return sweepSize_; }
    const Scene& scene() const { return scene_; }
    const std::vector<Camera>& cameras() const { return cameras_; }
    const TradeoffOptions& options() const { return o_; }

    // The GPU output a --buffer name reads; "ao" is the AO buffer the lighting
    // pass reads (this is the one place that says which); "shadow" is the
    // lighting pass's on-demand lighting.shadow (the reference's shadow
    // factor). Throws Error for unknown names.
    static std::string gpuOutput(const std::string& buffer);
    // The image a --buffer name measures, as the last frame of `session` left
    // it: raw floats (lbuffer, ao, shadow) or display values (final); the
    // AO's first channel alone. Throws Error for unknown names.
    static FloatImage measuredImage(RenderSession& session, const std::string& buffer);

    // Needs a current GL 4.5 context.
    TradeoffResult run(const TradeoffReference& reference, const BenchProgress& progress = {});
    // Where run() sends its warnings, one line each: AOV's cost (a point and
    // camera over AovCostEstimate's limits, before any frame) and what the
    // passes lost in a point's timed frames (FrameWarnings: the oit pass's
    // fragments). stderr when unset (the CLI); TradeoffStudy::measure sends
    // them to its progress' warning.
    void setWarningSink(std::function<void(const std::string&)> sink) { warning_ = std::move(sink); }

private:
    // The constructor's steps (TradeoffRunner.cpp).
    void checkOptions() const;
    void readAxes(const KnobRegistry& declared);
    static void readAxisValue(const KnobRegistry& declared, TradeoffAxis& axis, std::string& text);
    void readAgainst(const KnobRegistry& declared);
    void placeCameras();
    void planPointRuns();
    Camera withPlanes(Camera camera, size_t point) const;
    // run()'s stages and the helpers they share (TradeoffRunner.cpp).
    using Errors = std::vector<std::vector<ErrorEstimate>>;  // [point][camera]
    void applyPoint(RenderSession& session, size_t point) const;
    Camera cameraOf(size_t point, int camera) const;
    std::uint64_t pointSeed(size_t point, int camera) const;
    std::string describeConfiguration(int configuration) const;
    void warnAovCost(RenderSession& session) const;
    void warn(const std::string& line) const;
    void checkTimedPassName(RenderSession& session) const;
    // A --cost counter the driver lacks is refused before anything renders.
    void checkCostCounter() const;
    void checkTimedPass(const RunnerTimings& timings) const;
    FloatImage againstImage(RenderSession& session, const TradeoffReference& reference, int camera,
                            std::map<std::string, FloatImage>& rendered) const;
    Errors captureErrors(RenderSession& session, ConfigurationRunner& runner, const TradeoffReference& reference,
                         std::vector<std::string>& notes, const BenchProgress& say) const;
    // --metric temporal: per point, the path's frames rendered in order against
    // the reference's (TradeoffTemporal.cpp); the point's temporal error.
    std::vector<ErrorEstimate> capturePathErrors(RenderSession& session, ConfigurationRunner& runner,
                                                 const TradeoffReference& reference, std::vector<std::string>& notes,
                                                 const BenchProgress& say) const;
    void tabulate(TradeoffTable& table, const RunnerTimings& timings, const Errors& errors,
                  const std::vector<ErrorEstimate>& pathErrors, std::vector<std::string>& notes,
                  const BenchProgress& say) const;
    void noteMissingCameras(size_t point, const std::vector<double>& values, std::vector<std::string>& notes,
                            const BenchProgress& say) const;
    std::string frontTimeText() const;
    BenchFields settingsOf(const TradeoffResult& result, double totalSeconds,
                           const std::vector<std::string>& notes) const;

    std::function<void(const std::string&)> warning_;
    TradeoffOptions o_;
    Scene scene_;
    std::vector<TradeoffPoint> points_;
    size_t sweepSize_ = 0;
    std::vector<Camera> cameras_;
    std::vector<RunConfig> pointRuns_;  // per point: the run with the point's preset
    std::vector<KnobAssignment> against_;  // --against's knob values, as read once
};

}  // namespace dw
