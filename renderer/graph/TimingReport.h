#pragma once
// The timings of a run, made once and shown many ways (DESIGN.md: "one timing
// report serves render, bench, tradeoff and the window alike"): per pass and
// per span inside a pass ("lighting/shadow maps"), GPU and CPU median, min,
// max and mean over the counted frames only (warm-up frames, such as the
// first one with llvmpipe's shader compiles, are left out), plus the frame
// total. It prints the table of `render --timings` and serialises to JSON and
// CSV rows, which a sweep can prefix with its own columns.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/graph/PassTimer.h"
#include "renderer/graph/Pipeline.h"

namespace dw {

struct TimingRow {
    enum class Kind { Pass, Span, Total };
    Kind kind = Kind::Pass;
    std::string series;  // the timer's name: "lighting", "lighting/shadow maps", "frame"
    std::string pass;    // the pass it belongs to ("" for the total)
    bool ran = true;
    std::string reason;  // why the pass did not run (it then has no numbers)
    std::string stats;   // the pass's own line about its work
    TimingStats gpu, cpu;  // count: samples within the counted frames
    // Passes and the total, with counting on (PassTimer::setCounting): the
    // last counted frame's cost counters; `countsDiffer` names the first
    // counted frame whose counters differ from it (0 and false: all the same).
    PassCounts counts;
    bool countsDiffer = false;
    std::uint64_t differingFrame = 0;
};

class TimingReport {
public:
    // Frames firstFrame .. last.frameIndex (FrameReport::frameIndex values) are
    // counted; `warmup` says how many were rendered before them, for the
    // record. Rows follow `last`'s passes in pipeline order, each followed by
    // its spans. Waits for the timer's outstanding frames (collect(true)).
    static TimingReport build(PassTimer& timer, const FrameReport& last, std::uint64_t firstFrame, int warmup);

    const std::vector<TimingRow>& rows() const { return rows_; }
    const TimingRow* find(const std::string& series) const;
    const TimingRow& total() const { return rows_.back(); }
    int countedFrames() const { return total().gpu.count; }
    int warmupFrames() const { return warmup_; }

    // What render --timings prints: a line per pass (skipped ones with the
    // reason), its spans indented, its stats line, then the frame total;
    // then, when counted, the cost counters per pass and their frame sums.
    std::string table() const;
    // The counters' table alone ("" when nothing was counted).
    std::string countersTable() const;
    bool counted() const { return total().counts.measured(); }
    // {"frames", "warmup", "passes": [{name, ran, reason | stats, frames,
    // gpu_ms {median, min, max, mean}, cpu_ms {...}, spans: [...],
    // counters {fragments, samples, ...} when counted}], "total"}
    std::string json() const;
    static std::string csvHeader();
    // One line per row (no newline), the columns of csvHeader().
    std::vector<std::string> csvRows() const;
    std::string csv() const;  // header and rows, newline-terminated
    // Writes json() to a .json path, csv() to anything else; throws FileError.
    void write(const std::string& path) const;

private:
    std::vector<TimingRow> rows_;  // the last one is the total
    int warmup_ = 0;
};

}  // namespace dw
