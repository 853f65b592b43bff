#pragma once
// Several studies in one `tradeoff` run (--study, --study-file, Python
// studies=): each study a grid of its own knobs (a knob given one value is
// fixed), their points listed one after another in one sweep (TradeoffSweep's
// listed points) with the label axis "study" naming each point's study, so
// one run measures them all: one CSV, one front across every point, one
// table, one plot, one pick, one record (docs/tradeoffs.md, "One study, one
// record").
//   Axes: "study" first, then every knob any study sweeps, in the order they
//     first appear. A point's knob that its study does not name holds the
//     run's current value (its preset, --set and scene), written as the knob
//     writes it, so the CSV and the record say every value a point ran with.
//   Refused (TradeoffStudyError, one line): an empty study, a knob named twice
//     in a study, an empty value, an unknown knob or a value it does not take,
//     two studies of one name, and a point given twice (in one study or two);
//     in a study file, a key JSON gives twice (two studies of one name, a knob
//     twice in one study), which the parser would keep once.
// Needs no GL; sweep() needs the current knobs (the run's on its scene).
#include <string>
#include <vector>

#include "renderer/Error.h"
#include "renderer/bench/TradeoffSweep.h"
#include "renderer/knobs/KnobRegistry.h"

namespace dw {

// Bad study input: the CLI's usage error (exit 2), Python's ValueError.
class TradeoffStudyError : public Error {
public:
    using Error::Error;
};

struct TradeoffStudySpec {
    std::string name;  // "" until named: the values of its one-value knobs ("ssao"), else "study N"
    struct Knob {
        std::string name;
        std::vector<std::string> values;  // as --set takes them; one value: the knob is fixed
    };
    std::vector<Knob> knobs;  // in the order given
    std::string origin;       // where it was given, for messages: "--study", "--study-file F", "studies"
};

class TradeoffStudies {
public:
    // "[NAME:]KNOB=V1,V2[:KNOB=V...]" (--study). Throws TradeoffStudyError.
    static TradeoffStudySpec parse(const std::string& text);
    // A study file: a JSON object {"NAME": {"KNOB": value or [values], ...}, ...}
    // (the studies in the file's order) or an array of {"KNOB": ...} objects
    // (named as --study names them). FileError for an unreadable or malformed
    // file; TradeoffStudyError for a bad study.
    static std::vector<TradeoffStudySpec> readFile(const std::string& path);
    // Names each unnamed study and checks what needs no knobs: at least one
    // study, none empty, no knob twice, no empty value, no name twice.
    static std::vector<TradeoffStudySpec> named(std::vector<TradeoffStudySpec> studies);
    // The listed sweep of named() studies, the knobs read against `current`
    // (the run's knobs on its scene: unknown knobs and bad values refused, each
    // value written as the knob writes it, the unnamed knobs' values from it);
    // a point given twice is refused.
    static TradeoffSweep sweep(const std::vector<TradeoffStudySpec>& studies, const KnobRegistry& current);
};

}  // namespace dw
