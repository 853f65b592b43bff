#pragma once
// What a change cost, per pass: when a knob changes, the frames timed before
// it are kept as "before", the frames timed after it (once `settle` frames
// have passed, so re-created resources and recompiled shaders are not
// counted) as "after", and each pass gets the median before and after, the
// difference and a 95% percentile-bootstrap interval of the ratio of medians
// (renderer/bench/Bootstrap.h, as `bench` reports ratios). A change is
// significant when that interval leaves out 1. The workbench's timings panel
// shows it as "ssao +44.0 ms (+63%, 95% CI 58-69%)". No GL: it reads the
// PassTimer's history, so it is tested with synthetic samples.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/bench/Bootstrap.h"
#include "renderer/graph/PassTimer.h"

namespace dw {

struct PassChangeCost {
    std::string pass;
    double beforeMs = 0.0, afterMs = 0.0;  // medians, GPU ms
    int beforeFrames = 0, afterFrames = 0;
    RatioInterval ratio;                   // after / before, with its 95% interval
    bool significant() const { return ratio.valid() && (ratio.low > 1.0 || ratio.high < 1.0); }
    // "+44.0 ms (+63%, 95% CI +58% to +69%)"; "new: 3.2 ms" for a pass that
    // runs only since; "no frames since" before the first frame after.
    std::string describe() const;
};

class ChangeCost {
public:
    // A change happened after frame `lastFrameBefore` was rendered: the
    // newest `window` samples of every series up to it become "before".
    // Samples of frames before `firstFrame` (the first frames after a reset,
    // which compile shaders) are no baseline and are left out.
    void mark(const PassTimer& timer, std::uint64_t lastFrameBefore, std::string what, size_t window = 120,
              std::uint64_t settle = 3, std::uint64_t firstFrame = 0);
    bool active() const { return active_; }
    void clear() { *this = ChangeCost(); }
    const std::string& what() const { return what_; }
    // Every series with frames before the change, in the order of the
    // timer's series; "after" from the frames timed since (at most `window`).
    std::vector<PassChangeCost> costs(const PassTimer& timer) const;
    // Frames timed after the change so far (of the frame series).
    int afterFrames(const PassTimer& timer) const;

private:
    bool active_ = false;
    std::string what_;
    std::uint64_t firstAfter_ = 0;
    size_t window_ = 120;
    std::vector<std::pair<std::string, std::vector<double>>> before_;
};

}  // namespace dw
