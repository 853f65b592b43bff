#pragma once
// The sweep behind the Pareto panel's *fit budget* (issue 34 part 3, mission
// row 64, in the window): the points `tradeoff --knobs speed/quality` sweeps
// about the current settings (TradeoffSweep::aroundCurrent: every knob the
// registry marks as trading speed for quality, one at a time, a bool both
// ways, an enum every choice, a number x1/4, x1/2, x2, x4 of its value), each
// rendered on the stepping ConfigurationRunner bench and tradeoff use (rounds,
// a warm-up frame after each switch, `frames` counted frames a point; one
// frame a step, a step a UI frame, every knob put back after each step, so
// the window stays responsive and the viewport never shows a swept point).
// Per point:
//   time   `time` as tradeoff --time takes it (frame, a pass, a span
//          PASS/NAME or a sum a+b+c: the per-frame sum), the median over the
//          counted frames with its 95% bootstrap interval, in GPU ms;
//   error  FLIP (mean) of the final image (display values) against a
//          baseline (the CPU reference of the view, or the current image by
//          choice) with its 16x16-tile bootstrap interval (ImageError).
// Then the front by the intervals rule (TradeoffTable::markParetoFront) and
// the budget's pick (BudgetPicker: the least-error point whose time's 95%
// interval ends under the budget; none fits: the cheapest point, nothing
// picked). Points whose AOV frame at the view's size is over
// AovCostEstimate's limits are left out (the live view's guard would put
// them back) and counted. The session's knobs and camera are the same after
// every step as before it: each frame renders the settings and the camera the
// sweep started from (a camera moved meanwhile does not change what is
// measured); another scene or another render size stops the run. The
// settings the sweep is about are kept (previous()).
// Errors: start() throws dw::Error, one line, before anything renders: a
// budget out of tradeoff --budget-ms's range (BudgetPicker::check), an empty term or a pass the pipeline
// lacks in `time`, no speed/quality knob to sweep. A failing frame stops the
// run (error()). step() needs the session's current GL context.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/bench/BudgetPick.h"
#include "renderer/bench/ConfigurationRunner.h"
#include "renderer/bench/ImageError.h"
#include "renderer/bench/TradeoffSweep.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/io/ImageIO.h"
#include "renderer/scene/Camera.h"

namespace dw::ui {

struct FitBudgetSettings {
    double budgetMs = 0.0;        // GPU ms, finite and above 0
    std::string time = "frame";   // frame, a pass, PASS/NAME or a+b+c (tradeoff --time)
    int frames = 6;               // counted frames a point: 6 is the fewest a time interval is claimed from
    int warmup = 1;               // frames left out after each switch to a point
};

class FitBudgetRun {
public:
    // Throws dw::Error naming what is wrong with the budget or the time
    // (its terms against `session`'s pipeline passes).
    static void check(const FitBudgetSettings& settings, RenderSession& session);
    // check(), then plans the sweep about `session`'s knobs, camera and size.
    // `baseline`: the final image every point is measured against (display
    // values, the view's size), named `baselineName`.
    void start(RenderSession& session, FloatImage baseline, std::string baselineName, const FitBudgetSettings& settings);
    // Renders the next frame (a point's warm-up or counted frame); true while
    // frames remain. On the last it reads the timer, builds the table and picks.
    bool step(RenderSession& session);
    void cancel() { running_ = false; }

    bool running() const { return running_; }
    bool done() const { return done_; }
    std::uint64_t finished() const { return finished_; }  // runs that ended with a table (a new result when it moves)
    double progress() const;                                // counted frames rendered over all, 0..1
    size_t points() const { return points_.size(); }        // the points measured
    size_t leftOut() const { return leftOut_; }             // the points over the AOV cost limit, left out
    const std::string& error() const { return error_; }     // why the last run stopped ("" when it finished)
    const std::string& baselineName() const { return baselineName_; }
    const FitBudgetSettings& settings() const { return settings_; }
    const TradeoffTable& table() const { return table_; }
    const BudgetPick& pick() const { return pick_; }
    // The settings the sweep is about (the knobs when it started).
    const KnobRegistry& previous() const { return *previous_; }
    // The knob values of point `point` (its number) as --set takes them: knob=value, one per axis.
    std::vector<std::string> assignmentsOf(int point) const;

private:
    void planPoints(RenderSession& session);
    bool sameView(RenderSession& session);
    void beginRunner(RenderSession& session);
    void measureError(RenderSession& session, size_t configuration);
    void finish();
    TradeoffRow rowOf(size_t configuration, const std::map<int, std::map<int, double>>& ranked,
                      const std::map<int, std::map<int, double>>& frame) const;

    FitBudgetSettings settings_;
    std::unique_ptr<KnobRegistry> previous_;
    Camera camera_;            // the camera the sweep started with
    std::string sceneSource_;  // the scene it started on
    TradeoffSweep sweep_;
    std::vector<TradeoffPoint> points_;  // those measured (configuration i is points_[i])
    size_t leftOut_ = 0;
    FloatImage baseline_;
    std::string baselineName_, error_;
    std::vector<ErrorEstimate> errors_;  // per configuration; NaN until measured
    std::unique_ptr<ConfigurationRunner> runner_;
    RenderSession* session_ = nullptr;  // the session the first step was given
    int selected_ = -1;                 // the configuration the runner set in this step
    bool running_ = false, done_ = false;
    std::uint64_t finished_ = 0;
    TradeoffTable table_;
    BudgetPick pick_;
};

}  // namespace dw::ui
