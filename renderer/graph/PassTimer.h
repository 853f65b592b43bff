#pragma once
// Per-pass GPU time from glQueryCounter(GL_TIMESTAMP) pairs, plus the CPU time
// spent issuing each pass. Results are harvested frames later, when
// GL_QUERY_RESULT_AVAILABLE says so, so the CPU never waits on the GPU (bgfx's
// TimerQueryGL and Magnum's FrameProfilerGL do the same); a short history per
// pass feeds the timer graphs and the medians `render --timings` prints.
// With counting on, each pass also carries its cost counters (PassCounts.h:
// GL pipeline statistics and samples-passed queries begun and ended around
// it, from a pool, harvested with its timestamps; the frame's counts are the
// sums over its passes).
#include <chrono>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "renderer/gl/CounterQuery.h"
#include "renderer/gl/TimestampQuery.h"
#include "renderer/graph/PassCounts.h"

namespace dw {

struct TimingSample {
    std::uint64_t frame = 0;
    float gpuMs = 0.0f;
    float cpuMs = 0.0f;
    PassCounts counts;  // passes and "frame" when counting; else none measured
};

struct TimingStats {
    int count = 0;
    float median = 0, mean = 0, min = 0, max = 0;
};
TimingStats computeStats(std::vector<float> values);

class PassTimer {
public:
    static constexpr size_t kHistory = 600;  // samples kept per series, unless set otherwise
    static constexpr const char* kFrameSeries = "frame";

    struct Series {
        std::string name;
        std::deque<TimingSample> samples;
    };

    void beginFrame(std::uint64_t frame);
    void beginPass(const std::string& name);
    void endPass();
    // A part of the current pass with its own series "<pass>/<name>"; spans of
    // the same name in one frame are added up (e.g. every shadow map).
    void beginSubSpan(const std::string& name);
    void endSubSpan();
    void endFrame();
    // Drops the frame in progress (a pass threw); its queries go back to the pool.
    void abortFrame();
    // Moves finished frames into the history. With wait=true blocks until all
    // outstanding frames are done (the CLI's last step; never in a frame loop).
    void collect(bool wait = false);

    const std::vector<Series>& series() const { return series_; }
    const Series* find(const std::string& name) const;
    // Over the newest `window` samples of a series (all, if 0).
    TimingStats gpuStats(const std::string& name, size_t window = 0) const;
    TimingStats cpuStats(const std::string& name, size_t window = 0) const;
    size_t pendingFrames() const { return pending_.size(); }
    void clearHistory();
    // Drops the samples of frames before `frame` (a configuration that
    // started with it: the frames of the one before no longer compare),
    // also those still in flight: their results, when they come back, are
    // not recorded.
    void clearHistoryBefore(std::uint64_t frame);
    // Samples kept per series (kHistory by default); a run that reports on
    // more frames than that (render --frames N) raises it so none drop out.
    void setHistoryLength(size_t samples);
    size_t historyLength() const { return historyLength_; }
    // Records a finished sample of a series, as harvesting does (kept unless
    // paused, oldest dropped beyond the history length). Timing reports are
    // tested with synthetic histories made through it, without GL.
    void addSample(const std::string& series, const TimingSample& sample);
    // While paused, finished frames are still harvested but not recorded, so
    // the history on screen holds still.
    void setPaused(bool paused) { paused_ = paused; }
    bool paused() const { return paused_; }
    // Own CPU time per pass: before each pass starts, wait (on a fence) until
    // the GPU has finished everything before it, so a pass's CPU time is what
    // it spends itself, not a wait for earlier GPU work that the driver
    // happens to charge to it (e.g. a read-back). Slows the frame; off by default.
    void setIsolateCpu(bool on) { isolateCpu_ = on; }
    bool isolateCpu() const { return isolateCpu_; }
    // Cost counters per pass (PassCounts.h), from the next frame on: the
    // pipeline statistics only where the driver has them
    // (gl::hasPipelineStatistics), samples passed always. Needs a context
    // when turned on. Off by default.
    void setCounting(bool on);
    bool counting() const { return counting_; }
    // The bytes the current pass's declared resources take (the pipeline
    // says, before endPass); only while counting.
    void setPassBytes(std::int64_t bytes);
    // The recorded history as CSV: frame, series, gpu_ms, cpu_ms.
    std::string csv() const;
    // Writes csv() to `path`; throws FileError.
    void writeCsv(const std::string& path) const;

private:
    struct Span {
        std::string name;
        gl::TimestampQuery begin, end;
        float cpuMs = 0.0f;
        gl::CounterQueries counters;  // a pass's, while counting
        std::int64_t bytes = -1;
    };
    struct PendingFrame {
        std::uint64_t frame = 0;
        std::vector<Span> spans;
    };
    gl::TimestampQuery acquire();
    gl::CounterQueries acquireCounters();
    void release(Span& span);
    Series& seriesFor(const std::string& name);
    void harvest(PendingFrame& f);

    std::vector<gl::TimestampQuery> pool_;
    std::vector<gl::CounterQueries> counterPool_;
    bool counting_ = false, statistics_ = false;
    std::deque<PendingFrame> pending_;
    PendingFrame current_;
    bool inFrame_ = false;
    bool inPass_ = false;
    bool inSubSpan_ = false;
    bool paused_ = false;
    bool isolateCpu_ = false;
    size_t historyLength_ = kHistory;
    std::uint64_t floor_ = 0;  // samples of earlier frames are not recorded (clearHistoryBefore)
    std::string passName_;
    size_t passIndex_ = 0;
    std::chrono::steady_clock::time_point subStart_;
    std::chrono::steady_clock::time_point passStart_, frameStart_;
    std::vector<Series> series_;
};

}  // namespace dw
