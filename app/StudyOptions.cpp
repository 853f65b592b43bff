#include "app/StudyOptions.h"

namespace dw {

StudyOptions StudyOptions::read(CommandLine& cl) {
    StudyOptions o;
    const std::vector<std::string> given = cl.values("--study");
    o.file = cl.value("--study-file");
    try {
        if (o.file) o.studies = TradeoffStudies::readFile(*o.file);
        for (const auto& text : given) o.studies.push_back(TradeoffStudies::parse(text));
    } catch (const Error& e) {  // a bad study, or a study file missing or not JSON: usage errors (exit 2)
        throw UsageError(e.what());
    }
    return o;
}

std::string StudyOptions::help() {
    return "  --study      [NAME:]KNOB=V1,V2[:KNOB=V...]: a study, the grid of its own knobs (one value: fixed);\n"
           "               repeat it for several in one run: one CSV (the column study), one front across every\n"
           "               point, one table, plot, pick and record. A knob a study does not name keeps the run's\n"
           "               value. NAME defaults to its fixed knobs' values (ssao). Not with --sweep, --presets, --knobs\n"
           "  --study-file F.json  studies from a file: {\"NAME\": {\"KNOB\": value or [values], ...}, ...}\n"
           "               (docs/tradeoffs.md); before any --study\n";
}

}  // namespace dw
