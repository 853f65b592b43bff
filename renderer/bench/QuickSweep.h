#pragma once
// A quick sweep of one knob in the current view (issue 23, the workbench's
// Pareto panel): each of the knob's values rendered a few times, one frame a
// step so a window stays responsive, the values interleaved as bench
// interleaves its configurations; each value's final image measured against
// a baseline (the CPU reference's final image when one is given, else the
// current settings' image) with FLIP, and its GPU frame times taken from the
// pipeline's timer. The result is a TradeoffTable (axis: the knob; camera
// "0", metric "flip", buffer "final"; the frame time's median with its 95%
// bootstrap interval; no error interval: one image a value) with its Pareto
// front marked, what the panel plots for a tradeoff CSV.
// Values: an enum's choices, a switch's two, an integer's or a float's range
// at up to five points (geometric on a logarithmic knob). The knob is put
// back after every frame, so the session's settings never change.
// Errors: Error naming the knob when it is not declared.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/io/ImageIO.h"

namespace dw {

class QuickSweep {
public:
    // The values swept for `knob` (as --set takes them).
    static std::vector<std::string> valuesOf(const KnobRegistry& knobs, const std::string& knob);

    // `baseline`: the image every value is measured against (final, display values, rows top-down).
    void start(const KnobRegistry& knobs, const std::string& knob, FloatImage baseline, std::string baselineName,
               int framesPerValue = 3);
    // Renders the next frame; true while frames remain. On the last it reads
    // the timer (waiting for its results) and builds the table.
    bool step(RenderSession& session);
    void cancel() { running_ = false; }

    bool running() const { return running_; }
    bool done() const { return done_; }
    double progress() const { return total_ ? static_cast<double>(next_) / total_ : 0.0; }
    const std::string& knob() const { return knob_; }
    const std::string& baselineName() const { return baselineName_; }
    const std::string& error() const { return error_; }  // why the last sweep stopped ("" when it finished)
    const TradeoffTable& table() const { return table_; }

private:
    void finish(RenderSession& session);
    std::string knob_, baselineName_, error_;
    std::vector<std::string> values_;
    FloatImage baseline_;
    int framesPerValue_ = 3, total_ = 0, next_ = 0;
    std::vector<double> flip_;                     // per value; NaN until measured
    std::map<std::uint64_t, size_t> frameValue_;   // rendered frame -> value index
    bool running_ = false, done_ = false;
    TradeoffTable table_;
};

}  // namespace dw
