#pragma once
// What a `bench` run measured, in the form it is written and read back: the
// configurations (with their lights per pixel), every counted frame's
// per-series GPU and CPU milliseconds, the machine and the run's settings.
// The samples CSV carries everything the summary needs, one row per frame
// and series:
//   config,size,lights,<knob>...,lpp,lpp_lit,sample,seq,frame,pass,gpu_ms,cpu_ms,gpu_mem_peak_mib
// and, when counted, the row's cost counters (PassCounts.h; a pass's own, the
// frame row's their sums; empty for a span or where not measured):
//   ...,cpu_ms,fragments,samples,primitives,vertices,compute,bytes
// so `bench merge` can join shards from CSV alone and recompute the table.
// Needs no GL.
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "renderer/bench/BenchGrid.h"
#include "renderer/gl/CompiledShaders.h"
#include "renderer/graph/PassCounts.h"

namespace dw {

struct BenchSample {
    int config = 0;             // BenchConfig::index
    int sample = 0;             // the counted frame's number within its configuration, 0..frames-1
    long long seq = 0;          // the order it was rendered in across the whole run (for drift)
    std::uint64_t frame = 0;    // the session's frame index
    std::string series;         // a pass, a span ("lighting/shadow maps") or "frame" (the whole frame)
    double gpuMs = 0.0, cpuMs = 0.0;
    PassCounts counts;          // the pass's (the frame's: their sums) cost counters; none for a span
    // The frame's peak GPU memory, MiB (bytes / 2^20, exact in a double):
    // the largest its session's pipeline held during the frame (logical
    // bytes, gl/MemoryLedger.h; ConfigurationRunner). The same on every row of
    // a frame. NaN: not measured (a CSV from before the column).
    double gpuMemPeakMib = std::numeric_limits<double>::quiet_NaN();
};

struct BenchConfigResult {
    BenchConfig config;
    // Lights per pixel (seed 000 table 6.1): the mean of lighting.overlap
    // over all pixels, and over the pixels at least one light reached. NaN
    // when not measured.
    double lpp = 0.0, lppLit = 0.0;
    // Each pass's own statistics line (PassRecord::stats) of the last counted
    // frame, e.g. the lighting pass's strategy, counts and auto's choice.
    // Only in this run's JSON: the CSV (and so bench merge) does not carry it.
    std::map<std::string, std::string> stats;
};

// A configuration's peak GPU memory in MiB: the largest of its samples'
// (NaN when none was measured).
double gpuMemPeakMib(const std::vector<BenchSample>& samples, int config);

using BenchFields = std::vector<std::pair<std::string, std::string>>;  // ordered name -> value

struct BenchResults {
    std::vector<std::string> knobAxes;        // the knob columns, in order
    std::vector<BenchConfigResult> configs;   // by index, ascending
    std::vector<BenchSample> samples;         // by config, then sample, then series in pipeline order
    BenchFields machine;                      // GL renderer, CPU, compiler, build ...
    BenchFields settings;                     // scene, frames, warm-up, seed ...
    gl::CompiledShaders shaders;              // the shader files the run compiled (none when read from a CSV)
    bool counted = false;                     // the CSV carries the counter columns

    const BenchConfigResult* find(int config) const;
    // The counters of a configuration are exact, so every counted frame of it
    // should count the same (a moving camera aside): "" when they do, else
    // the first that does not ("configuration 3, sample 2: lighting's
    // fragments 1200 (sample 0: 1180)").
    std::string counterMismatch() const;
    // The series of a configuration's frames in the order they were recorded.
    std::vector<std::string> seriesOf(int config) const;

    std::string csv() const;
    // The rows of `samples` (configurations from this->configs), without the header line.
    std::string csvRows(const std::vector<BenchSample>& samples) const;
    static std::string csvHeader(const std::vector<std::string>& knobAxes, bool counted = false);
    // Reads csv() back; throws FileError naming the file and line.
    // `cutLastLine`: a last line without its newline (a run killed while
    // writing it) is left out instead of refused (bench --resume).
    static BenchResults parseCsv(const std::string& text, const std::string& path, bool cutLastLine = false);
    static BenchResults readCsv(const std::string& path, bool cutLastLine = false);
    // Writes csv() whole or not at all (writeBenchFile). Throws FileError.
    void writeCsv(const std::string& path) const;

    // Joins shards of one grid: the same knob columns, no configuration in
    // two parts. Throws Error naming the clash. Machines and settings are the
    // first part's (bench merge records each shard's own beside them).
    static BenchResults merge(std::vector<BenchResults> parts, const std::vector<std::string>& names);
};

// Writes a file of bench's: a regular file whole or not at all (a temporary
// file renamed over it, so a failed write leaves the old one and no part of
// the new), a device or a pipe in place. Throws FileError naming `what`.
void writeBenchFile(const std::string& path, const std::string& text, const std::string& what);

}  // namespace dw
