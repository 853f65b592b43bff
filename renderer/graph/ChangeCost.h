#pragma once
// What a knob change costs, per pass, measured the way `bench` measures
// (renderer/bench/): the workbench renders frames with the knobs at their
// values before the change and after it, interleaved in short turns
// (B B A A B B ... with the first frame of each turn left out, so re-created
// resources and recompiled shaders are not counted), and compares each
// pass's GPU times of the two sides: medians, the difference and a
// percentile-bootstrap interval of the ratio of medians.
//
// Many passes are compared at once, so the verdict accounts for it: a pass
// the change cannot influence (it neither reads a changed knob nor reads
// anything such a pass writes, directly or further down) is reported but
// never flagged, and the intervals of the others are Bonferroni-adjusted for
// their number (95% for all of them together). No GL here: the tests feed
// synthetic samples.
//
// KnobChangeWatcher names the change by the values the user committed (a
// slider let go, a typed value entered), not by each keystroke in between.
// The measurement itself (the frames of both sides, interleaved) runs on the
// stepping ConfigurationRunner: renderer/bench/ChangeMeasurement.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "renderer/metrics/Bootstrap.h"
#include "renderer/graph/PassTimer.h"
#include "renderer/knobs/KnobRegistry.h"

namespace dw {

class Pipeline;

// The knobs a committed edit changed, with their values before and after it.
struct KnobChange {
    std::vector<int> knobs;
    std::vector<double> before, after;
    std::string what;  // "ssao.samples 16 -> 64", "... and 2 more"
    bool empty() const { return knobs.empty(); }
};

class KnobChangeWatcher {
public:
    // The current values are the committed ones.
    void reset(const KnobRegistry& knobs);
    // Called once a UI frame. `editing`: a widget is being edited (a slider
    // held, a value being typed), so the values are not committed yet and
    // nothing is reported. Otherwise a change of any value since the last
    // committed state is reported once, against that state (16 -> 64 for a
    // typed "64", never 16 -> 6 -> 64).
    std::optional<KnobChange> update(const KnobRegistry& knobs, bool editing);
    const std::vector<double>& committed() const { return committed_; }

private:
    std::vector<double> committed_;
    std::uint64_t generation_ = ~0ull;
};

// A pass's reads and writes, for working out what a change can reach
// (Pipeline::passList gives them; a pass that modifies a resource reads and writes it).
struct PassEdges {
    std::string name;
    std::vector<std::string> reads, writes;
};
// The passes that read a knob (`readers`; "*" for the whole pipeline) and
// every pass that reads what an influenced pass writes, transitively.
// `passes` in pipeline order.
std::set<std::string> influencedPasses(const std::vector<PassEdges>& passes, const std::set<std::string>& readers);
// Whether a timer series belongs to an influenced pass: "lighting/shadow maps"
// to "lighting"; the frame total whenever any pass is influenced.
bool seriesInfluenced(const std::string& series, const std::set<std::string>& influenced);
// The pipeline's passes as edges (Pipeline::passList; optional reads and
// modified resources count as reads, modified ones as writes too).
std::vector<PassEdges> passEdges(const Pipeline& pipeline);
// What a change of `knobs` can reach in `pipeline`: influencedPasses from
// the passes that read them (Pipeline::knobReaders; a knob no pass is known
// to read counts as read by every pass).
std::set<std::string> passesReachedBy(const Pipeline& pipeline, const std::vector<int>& knobs);

struct PassVerdict {
    std::string pass;                      // a timer series
    double beforeMs = 0.0, afterMs = 0.0;  // medians, GPU ms
    int beforeFrames = 0, afterFrames = 0;
    RatioInterval ratio;      // after / before; at the adjusted level when influenced, else 95%
    double confidence = 0.95; // of `ratio`'s interval
    bool influenced = true;   // the change can reach this pass
    bool significant = false; // influenced and the interval leaves out 1
    // "+44.0 ms (+63%, 99.6% CI +58% to +69%)"; "new: 3.200 ms" for a pass that
    // runs only after the change, "gone (was 3.200 ms)" for one that stopped.
    std::string describe() const;
};

struct ChangeVerdict {
    std::vector<PassVerdict> passes;
    int compared = 0;             // influenced series with frames on both sides: the family
    double familyConfidence = 0.95;
    double perPassConfidence = 0.95;  // 1 - (1 - family) / compared (Bonferroni)
    int notInfluenced = 0;
    const PassVerdict* find(const std::string& pass) const;
    // "99.6% interval per pass (Bonferroni over 9 passes: 95% for all together); 5 passes the change cannot reach: not flagged"
    std::string method() const;
};

using SeriesSamples = std::map<std::string, std::vector<double>>;
// Judges the samples of the two sides: `influenced` as influencedPasses gives
// it (a series outside it is never flagged), `order` the series in the
// order to report them (others follow).
ChangeVerdict judgeChange(const SeriesSamples& before, const SeriesSamples& after, const std::set<std::string>& influenced,
                          const std::vector<std::string>& order = {}, double familyConfidence = 0.95, int resamples = 4000);

}  // namespace dw
