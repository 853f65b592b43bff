#pragma once
// A quick sweep of one knob in the current view (issue 23, the workbench's
// Pareto panel): each of the knob's values rendered a few times on the
// stepping ConfigurationRunner that bench and tradeoff use (one value a
// configuration: a warm-up frame after each switch, then one counted frame;
// one frame a step, a step a UI frame so a window stays responsive, the
// values interleaved in rounds); each value's final image measured against
// a baseline (the CPU reference's final image when one is given, else the
// current settings' image) with FLIP, and its GPU frame times taken from the
// runner's timestamps. The result is a TradeoffTable (axis: the knob; camera
// "0", metric "flip", buffer "final"; the frame time's median with its 95%
// bootstrap interval; no error interval: one image a value) with its Pareto
// front marked, what the panel plots for a tradeoff CSV.
// Values: an enum's choices, a switch's two, an integer's or a float's range
// at up to five points (geometric on a logarithmic knob). The knob is put
// back after every frame, so the session's settings never change.
// Errors: Error naming the knob when it is not declared.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/bench/ConfigurationRunner.h"
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
    // Renders the next frame (a value's warm-up after a switch, or its
    // counted frame; on the session the first step was given); true while
    // frames remain. On the last it reads the timer (waiting for its
    // results) and builds the table.
    bool step(RenderSession& session);
    void cancel() { running_ = false; }

    bool running() const { return running_; }
    bool done() const { return done_; }
    double progress() const;  // counted frames rendered over all, 0..1
    const std::string& knob() const { return knob_; }
    const std::string& baselineName() const { return baselineName_; }
    const std::string& error() const { return error_; }  // why the last sweep stopped ("" when it finished)
    const TradeoffTable& table() const { return table_; }

private:
    void beginRunner(RenderSession& session);
    void measureFlip(RenderSession& session, size_t value);
    void finish();
    std::string knob_, baselineName_, error_;
    std::vector<std::string> values_;
    FloatImage baseline_;
    int framesPerValue_ = 3;
    std::vector<double> flip_;  // per value; NaN until measured
    std::unique_ptr<ConfigurationRunner> runner_;
    RenderSession* session_ = nullptr;  // the session the first step was given
    int selected_ = -1;                 // the value the runner set in this step
    bool running_ = false, done_ = false;
    TradeoffTable table_;
};

}  // namespace dw
