#pragma once
// What `replay` and `replay --diff` print, in one place so both say it in the
// same words (docs/records.md): changed, added and removed files, the
// "inputs changed (N): ..." line, the record's own sha256s ("record
// edited"), timings old against new with the interval of their ratio, bench
// configurations and tradeoff rows old against new, and the verdicts
// ("image: ...", "bench: ...", "tradeoff: ...") with their exit codes
// (0 the same, 1 differs). Output goes to stdout.
#include <cmath>
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "renderer/metrics/Bootstrap.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/record/SceneFiles.h"

namespace dw::replay {

// A timing ratio (new / old) counts as a change when its whole 95% interval
// lies outside this band: run-to-run noise on a shared machine stays inside.
constexpr double kTimingBandLow = 0.8, kTimingBandHigh = 1.25;

// The first 16 hex digits of a sha256 ("unreadable" for none).
std::string shortHash(const std::string& h);

// The inputs found changed, each named, for the "inputs changed (N): ..."
// line. They never decide the exit code: the results do.
struct ChangedInputs {
    std::vector<std::string> names;
    void add(const std::string& name) { names.push_back(name); }
    // "inputs changed (N): a, b" or "inputs changed: none".
    void print() const;
};

// Each changed, added or removed file (a scene's or a shader), on a line of
// its own ("WHAT changed: PATH (sha256 old -> new)", "WHAT added: PATH
// (sha256 new; ADDEDWHY)", "WHAT removed: PATH (recorded sha256 old;
// REMOVEDWHY)"), each counted as a changed input "WHAT PATH".
void reportFileChanges(const std::string& what, const std::vector<SceneFileChange>& changes,
                       const std::string& removedWhy, ChangedInputs& inputs,
                       const std::string& addedWhy = "the record does not list it");

// The record's own sha256s: "record edited: ..." for inputs or results that
// no longer match them (each a changed input, "record inputs edited" /
// "record results edited"), or that the record holds none. `who` starts each
// line ("" for replay's one record, "A.json: " for --diff).
void reportSelfCheck(const ExperimentRecord& record, const std::string& who, ChangedInputs& inputs);

// Prints "  xRATIO [LOW, HIGH]" for new / old of two series' GPU medians,
// or why there is none, and returns the interval (invalid when none: such a
// timing never counts as moved). `markMoved` adds "(moved)" after an
// interval wholly outside the band.
RatioInterval printRatio(const std::vector<double>& now, const std::vector<double>& old, int resamples = 2000,
                         bool markMoved = false);
bool timingMoved(const RatioInterval& r);

// "timing NAME gpu median OLD -> NEW ms  xRATIO [LOW, HIGH]" for every
// series both lists hold, in `now`'s order.
void compareTimings(const std::vector<RecordedSeries>& old, const std::vector<RecordedSeries>& now);
// The series' cost counters, exactly, where both have them: "counters: the
// same (N compared, exactly)" (0) or "counters: moved: fragments.lighting A -> B, ..." (1);
// nothing printed and 0 when neither record counted.
int compareCounters(const std::vector<RecordedSeries>& old, const std::vector<RecordedSeries>& now);
// "image: identical" (returns 0) or "image: differs (sha256 OLD -> NEW)" (1).
int imageVerdict(const std::string& oldSha, const std::string& newSha);

// One bench configuration: its label (size, lights, knob=value...), lights
// per pixel and the ratio series' GPU ms per counted frame.
struct RecordedConfig {
    std::string label;
    double lpp = NAN;
    std::vector<double> gpuMs;
    double gpuMemPeakMib = NAN;  // NaN: not in the record (written before the column)
};
// A bench record's results by configuration index, `series` the ratio's.
std::map<int, RecordedConfig> recordedConfigs(const nlohmann::ordered_json& results, const std::string& series);

// Per configuration in `after` (its order) the line replay prints
// ("config I (LABEL): SERIES gpu median OLD -> NEW ms xRATIO [LOW, HIGH]  lpp
// OLD -> NEW", or "not in the record"), then each of `before` left over
// ("in the record, not run again"); verdict() prints "bench: the same (...)"
// (returns 0) or "bench: differs (...)" (1).
struct BenchComparison {
    // memoryDiffer: configurations whose peak GPU memory is not the same to
    // the byte (it is deterministic); memoryUnknown: not in both records.
    int lppDiffer = 0, moved = 0, memoryDiffer = 0, memoryUnknown = 0;
    size_t compared = 0;
    std::vector<std::string> notInRecord, notRunAgain;
    std::string series;
    int verdict() const;  // prints it
};
BenchComparison compareBench(std::map<int, RecordedConfig> before, const std::vector<std::pair<int, RecordedConfig>>& after,
                             const std::string& series, int resamples);

// Per row of `after` (point, camera, metric, buffer) the line replay prints:
// the error old -> new (same / differs) and the frame's GPU median with the
// interval of the difference. Frames: a row's own count, else these.
// The cost counters (when both tables have them) are compared exactly: a
// row whose counter moved prints "counters moved: fragments.lighting A -> B, ...".
// Also every other number the front and the pick used: the error's interval
// (exactly, as the error: "error_ci95 [a, b] -> [c, d] (moved; ...)"), the
// time --time names when it is not the frame's (its median and interval,
// "(moved)" by the frame time's rule), and each row's front, dominated_by,
// tied_with and pick: counted when `exactCost` (a counter --cost: the front is
// as exact as its inputs), else said as the times' noise. A counter only one
// side measured ("counters not measured here: ..." / "counters missing in the
// record: ..."), a term of a --time sum moved ("time term moved: ...") and a
// recorded median outside its own interval ("record inconsistent: ...") each
// count too; the caller sets `pickMoved` (reportPick) before verdict().
struct TradeoffComparison {
    int errorDiffer = 0, moved = 0, missing = 0, countersMoved = 0;
    int intervalDiffer = 0, timeMoved = 0, frontMoved = 0;
    // Rows with a counter only one side measured ("not measured here: ...",
    // "missing in the record: ..."), rows whose recorded median lies outside
    // its own recorded interval ("record inconsistent"), rows with a term of
    // --time's sum moved, and the budget's pick moved (set by the caller).
    int countersMissing = 0, inconsistent = 0, termsMoved = 0;
    // Rows whose peak GPU memory (exact) is not the same, both recorded.
    int memoryDiffer = 0;
    bool pickMoved = false;
    bool countersCompared = false, exactCost = false;
    std::string time = "frame";  // the span --time named, when both tables have it
    size_t rows = 0;
    int verdict() const;  // prints "tradeoff: the same (...)" (0) or "tradeoff: differs (...)" (1)
};
TradeoffComparison compareTradeoff(const TradeoffTable& before, const TradeoffTable& after, int framesBefore,
                                   int framesAfter, bool exactCost = false);

}  // namespace dw::replay
