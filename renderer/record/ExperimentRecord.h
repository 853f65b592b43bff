#pragma once
// An experiment record (issue 24): one JSON that holds what made a
// measurement, so `replay` can restore exactly that state, measure again and
// say what changed. docs/records.md describes every field. Version 2:
//   command  render, bench, tradeoff or gui (the window's File > Save record)
//   scene    the spec, its source and the sha256 of every file it reads: the
//            scene file, the glTF files a scene JSON names, each glTF's .bin
//            buffers and images, the sky's files (SceneFiles)
//   camera, camera_path (fixed, orbit poses, or the walkthrough's keyframes)
//   knobs    every knob's value as --set takes it (bench: before the sweep)
//   seeds    every random seed the command used (bench's lights, the
//            bootstrap's); size, frames, warmup, buffer
//   grid     bench: sizes, lights, sweep, block, light radius, orbit ...;
//            tradeoff: axes, exclusions, against, metric, buffer, cameras ...
//   shaders  the shader folder and the sha256 of every shader file the run
//            compiled (stage files, their #includes, params/ headers)
//   build    version, commit at configure time, compiler, flags, build type
//   gl, host
//   record_sha256  {inputs, results}: the sha256 of every field but results
//            (and itself), and of results (contentSha256), written with the
//            record; replay says "record edited" when they no longer match
//   results  render/gui: per timing series the counted frames' GPU and CPU ms
//            with the median and its bootstrap 95% interval, the buffer's
//            pixel sha256, metrics when the command computed any; bench: the
//            summary bench --json always wrote (machine, settings, axes,
//            baseline, configs with samples, ratios and intervals);
//            tradeoff: per point and camera its knobs, the error with its
//            interval (also in `metrics`: metric, buffer, against), the GPU
//            ms with intervals, and the Pareto front
// Version 1 (render --record before the bench and window records) still
// reads: its missing fields take the values a version 1 run had (a fixed
// camera, no seeds, no flags). A newer version is refused with its version
// named. Read through the JSON nesting guard (readJsonFile).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "renderer/graph/PassCounts.h"
#include <utility>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/RunConfig.h"
#include "renderer/bench/BenchRunner.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/bench/TradeoffRunner.h"
#include "renderer/record/RecordedFile.h"
#include "renderer/record/ShaderFiles.h"

namespace dw {

using RecordFields = std::vector<std::pair<std::string, std::string>>;

struct RecordedSeries {
    std::string name;  // a pass, a span ("lighting/shadow maps") or "frame"
    std::vector<double> gpuMs, cpuMs;  // one per counted frame
    PassCounts counts;  // the last counted frame's cost counters (none: not counted); replay compares them exactly
};

struct RecordedCameraPath {
    std::string mode = "fixed";  // fixed, orbit or walkthrough
    int orbitPoses = 0;
    std::vector<CameraKeyframe> keyframes;  // the scene's camera.path (walkthrough)
};

// What `bench` needs to run the same grid again.
struct RecordedBench {
    BenchOptions options;  // run.scene and run.sets (every knob) included
    std::string ratioOf = "frame";
    int resamples = 2000;
    bool merged = false;   // written by bench merge: no grid to run again
};

// What `tradeoff` needs to run the same sweep again.
struct RecordedTradeoff {
    TradeoffOptions options;           // run.scene and run.sets (every knob) included
    std::vector<std::string> exclude;  // the --exclude texts
    int aoRays = 64;
    std::uint32_t referenceSeed = 1;  // the CPU reference's AO sample seed (seeds.reference)
    // The reference's samples per pixel and filter (grid.ref_spp, grid.ref_filter:
    // tradeoff --ref-spp, --ref-filter); records before them read as 1 and box.
    int refSpp = 1;
    std::string refFilter = "box";
    // The run's own preset and --set: with a preset axis, replay starts from
    // these (every knob as --set would hide each point's preset).
    std::string runPreset;                // the --preset specs joined by " + " (as shown)
    std::vector<std::string> runPresets;  // each --preset, in order
    std::vector<std::string> runSets;
    bool merged = false;  // written by tradeoff merge: no sweep to run again
    // --search (BudgetSearch): replay walks again from the same start; its bound in evaluations.
    bool search = false;
    int maxEvals = 0;
};

struct ExperimentRecord {
    static constexpr int kVersion = 2;
    static constexpr std::uint64_t kBootstrapSeed = 12345;
    int version = kVersion;
    int readVersion = kVersion;  // the version the file had (1: migrated on reading)
    std::string command = "render";
    std::string sceneSpec, sceneSource;
    std::vector<RecordedFile> sceneFiles;
    RecordedShaders shaders;  // the shader folder and every shader file the run compiled (ShaderFiles)
    Camera camera;
    RecordedCameraPath cameraPath;
    RecordFields knobs;
    RecordFields seeds;
    int width = 0, height = 0, frames = 1, warmup = 0;
    double sceneTime = 0.0;  // --scene-time (seconds): the animation's pose; "scene_time", 0 when absent
    std::string animation;   // --animation (the clip that plays); "animation", absent: each file's first
    std::string buffer = "final";
    // render of a CPU reference buffer (reference.*, compare.error): the
    // trace's AO rays per pixel, samples per pixel and filter ("reference":
    // {"ao_rays", "spp", "filter"}; records before spp read as 1 and box) and
    // seed (seeds.reference), so replay traces the same reference; unset otherwise.
    std::optional<int> referenceAoRays;
    std::uint32_t referenceSeed = 1;
    int referenceSpp = 1;
    std::string referenceFilter = "box";
    RecordFields build, gl, host;
    std::vector<RecordedSeries> timings;
    std::vector<std::pair<std::string, double>> metrics;
    std::string imageSha256;
    int imageWidth = 0, imageHeight = 0, imageChannels = 0;
    std::optional<RecordedBench> bench;
    nlohmann::ordered_json benchResults;  // bench: the results object (benchResultsJson)
    std::optional<RecordedTradeoff> tradeoff;
    nlohmann::ordered_json tradeoffResults;  // tradeoff: the results object (tradeoffResultsJson)

    // What the record's own sha256s (record_sha256, written with it) say when
    // it is read: `hashed` false for a record written before records kept
    // them; `inputsEdited` / `resultsEdited` when the fields no longer match
    // (edited since it was written), so replay tells an edited record from a
    // changed machine.
    struct SelfCheck {
        bool hashed = false, inputsEdited = false, resultsEdited = false;
        std::string writtenInputs, writtenResults, nowInputs, nowResults;  // hex sha256s
    };
    SelfCheck selfCheck;
    // The sha256 of a record's JSON without `results` and `record_sha256`
    // (its inputs, build, GL and host: "inputs"), and of its `results`
    // ("results"), each over nlohmann::json's compact dump with sorted keys,
    // so indentation and key order do not count.
    static std::pair<std::string, std::string> contentSha256(const nlohmann::json& record);

    // After a run of `run` in `session` whose counted frames start at
    // `firstCounted` (waits for the timer's outstanding frames).
    static ExperimentRecord capture(RenderSession& session, const RunConfig& run, const std::string& buffer,
                                    std::uint64_t firstCounted, const std::string& glPlatform);
    // A bench run: its options (before the runner took them), the scene it
    // loaded, and what it measured.
    static ExperimentRecord forBench(const RecordedBench& bench, const Scene& scene, const BenchResults& results,
                                     const BenchSummary& summary);
    // From measured results alone (bench merge): no grid to run again.
    static ExperimentRecord forBenchResults(const BenchResults& results, const BenchSummary& summary);

    // A tradeoff run: its options, the scene it loaded, what it measured
    // (the table, the run's settings, the shader files it compiled);
    // `machine` the GL strings and platform.
    static ExperimentRecord forTradeoff(const RecordedTradeoff& tradeoff, const Scene& scene, const TradeoffResult& result,
                                        const BenchFields& machine);
    // From a table alone (tradeoff merge): no sweep to run again.
    static ExperimentRecord forTradeoffTable(const TradeoffTable& table, const BenchFields& settings);
    // A tradeoff record's rows back as a table (merge, replay). Throws FileError naming `path`.
    TradeoffTable tradeoffTable(const std::string& path) const;

    // The record as JSON. With `recordPath` (where it will be written), a
    // relative scene path (spec, source, files; relative to the working
    // directory) is written relative to the record's folder, so the record
    // and its scene can move together and replay from any directory; an
    // absolute path or a built-in scene's name stays as it is.
    std::string json(const std::string& recordPath = {}) const;
    // Throws FileError naming the file and what is wrong (a newer version, a
    // missing field, a field outside the range of the option it stands for:
    // size, frames, warm-up, bench's and tradeoff's grid, a camera scene/CameraCheck
    // refuses). A relative scene path is resolved against the record's
    // folder; when nothing is there, against the working directory (what a
    // record written before paths were kept relative to the record meant).
    static ExperimentRecord read(const std::string& path);
    static ExperimentRecord parse(const std::string& text, const std::string& path);
    static ExperimentRecord fromJson(const nlohmann::json& j, const std::string& path);
    void write(const std::string& path) const;

    // sha256 of `buffer` as written: display bytes or raw floats; sets the shape.
    static std::string hashBuffer(RenderSession& session, const std::string& buffer, int& width, int& height,
                                  int& channels);
    // Marks a render record as one of a CPU reference buffer traced with
    // `aoRays` rays per pixel, AO pattern seed `seed`, `spp` samples per pixel
    // and their `filter` (reference's --ao-rays, --seed, --spp, --filter).
    void setReference(int aoRays, std::uint32_t seed, int spp = 1, const std::string& filter = "box");
    // Every knob of `knobs` as name -> value text.
    static RecordFields knobFields(const KnobRegistry& knobs);
};

// An experiment record of bench results alone (bench merge's JSON; `bench`
// writes ExperimentRecord::forBench, which adds the grid, knobs and files).
// Here, above bench/: the runners know nothing of records.
std::string benchJson(const BenchResults& results, const BenchSummary& summary);
void writeBenchJson(const std::string& path, const BenchResults& results, const BenchSummary& summary);

}  // namespace dw
