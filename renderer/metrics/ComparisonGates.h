#pragma once
// Pass, warn or fail for an ImageComparison, the way OpenImageIO's idiff
// decides (idiff.cpp, OIIO 2.4; `idiff --help`):
//   fail  when more than failPercent % of the pixels have a channel whose
//         |reference - test| exceeds the fail threshold (ImageComparison's
//         failCount), or any |reference - test| exceeds hardFail;
//   warn  otherwise, when more than warnPercent % of the pixels exceed the
//         warn threshold (warnCount), or any difference exceeds hardWarn;
//   pass  otherwise.
// idiff's defaults: thresholds 1e-6, percentages 0, hard limits infinite.
// Beyond idiff: failFlip fails when the mean FLIP exceeds it, failSsim when
// the mean SSIM is below it (a metric that was not computed fails such a gate).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "renderer/metrics/ImageComparison.h"

namespace dw {

enum class Verdict { Pass = 0, Warn = 1, Fail = 2 };
const char* verdictName(Verdict v);

struct ComparisonGates {
    double failPercent = 0, warnPercent = 0;
    double hardFail = std::numeric_limits<double>::infinity();
    double hardWarn = std::numeric_limits<double>::infinity();
    std::optional<double> failFlip, failSsim;

    // The verdict, and in `reasons` each gate that was crossed, in words.
    Verdict judge(const ImageComparison& comparison, std::vector<std::string>& reasons) const;
};

}  // namespace dw
