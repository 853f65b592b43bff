#pragma once
// tradeoff's --study and --study-file (TradeoffStudies, docs/tradeoffs.md
// "One study, one record"): several grids in one run. Bad input is a
// UsageError of one line (exit 2) before anything renders; an unreadable
// study file a FileError.
#include <optional>
#include <string>
#include <vector>

#include "headless/CommandLine.h"
#include "renderer/study/TradeoffStudies.h"

namespace dw {

struct StudyOptions {
    std::vector<TradeoffStudySpec> studies;  // the study file's, then each --study in order
    std::optional<std::string> file;         // --study-file (a file the run reads)

    static StudyOptions read(CommandLine& cl);
    // The help lines of --study and --study-file.
    static std::string help();
};

}  // namespace dw
