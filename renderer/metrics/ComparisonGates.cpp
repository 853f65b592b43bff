#include "renderer/metrics/ComparisonGates.h"

#include <cstdio>

namespace dw {

const char* verdictName(Verdict v) {
    switch (v) {
        case Verdict::Pass: return "PASS";
        case Verdict::Warn: return "WARNING";
        case Verdict::Fail: return "FAILURE";
    }
    return "?";
}

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

Verdict ComparisonGates::judge(const ImageComparison& c, std::vector<std::string>& reasons) const {
    reasons.clear();
    const DifferenceStatistics& d = c.difference;
    const double pixels = static_cast<double>(d.pixelCount);
    bool fail = false, warn = false;
    if (static_cast<double>(d.overall.failCount) > failPercent / 100.0 * pixels) {
        fail = true;
        reasons.push_back(std::to_string(d.overall.failCount) + " pixels (" +
                          number(100.0 * static_cast<double>(d.overall.failCount) / pixels) + "%) differ by more than " +
                          number(d.failThreshold) + ", allowed " + number(failPercent) + "%");
    }
    if (d.overall.max > hardFail) {
        fail = true;
        reasons.push_back("the largest difference " + number(d.overall.max) + " exceeds --hardfail " + number(hardFail));
    }
    if (failFlip) {
        if (!c.flip) {
            fail = true;
            reasons.push_back("--fail-flip given but FLIP was not computed");
        } else if (c.flip->mean > *failFlip) {
            fail = true;
            reasons.push_back("mean FLIP " + number(c.flip->mean) + " exceeds " + number(*failFlip));
        }
    }
    if (failSsim) {
        if (!c.ssim) {
            fail = true;
            reasons.push_back("--fail-ssim given but SSIM was not computed");
        } else if (c.ssim->mean < *failSsim) {
            fail = true;
            reasons.push_back("mean SSIM " + number(c.ssim->mean) + " is below " + number(*failSsim));
        }
    }
    if (fail) return Verdict::Fail;
    if (static_cast<double>(d.overall.warnCount) > warnPercent / 100.0 * pixels) {
        warn = true;
        reasons.push_back(std::to_string(d.overall.warnCount) + " pixels (" +
                          number(100.0 * static_cast<double>(d.overall.warnCount) / pixels) + "%) differ by more than " +
                          number(d.warnThreshold) + ", allowed " + number(warnPercent) + "%");
    }
    if (d.overall.max > hardWarn) {
        warn = true;
        reasons.push_back("the largest difference " + number(d.overall.max) + " exceeds --hardwarn " + number(hardWarn));
    }
    return warn ? Verdict::Warn : Verdict::Pass;
}

}  // namespace dw
