#pragma once
// Whether a number read from a file or the command line can be stored as the
// 32-bit float the renderer uses: finite as a double is not enough (1e39
// becomes +inf as a float). Shared by the scene JSON, preset, glTF and knob
// readers so they refuse the same values with the same words.
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>

namespace dw {

// The number as a short text ("1e+39").
inline std::string shortNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// Empty when `v` is a finite 32-bit float; otherwise what is wrong, in words
// that follow a field name: "1e+39 does not fit a 32-bit float (largest about 3.4e38)".
inline std::string floatProblem(double v) {
    if (std::isnan(v)) return "is not a number";
    if (std::isinf(v)) return "expected a finite number";
    if (std::fabs(v) > static_cast<double>(FLT_MAX))
        return shortNumber(v) + " does not fit a 32-bit float (largest about 3.4e38)";
    return {};
}

}  // namespace dw
