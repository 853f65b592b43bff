#pragma once
// Facts about the machine a measurement ran on, for bench's JSON and the
// experiment records (the GL strings come from the GL context).
#include <string>

namespace dw {

// /proc/cpuinfo's first "model name", or "unknown".
std::string cpuModel();
// The compiler that built this binary ("gcc 12.2.0", "clang 14.0.6").
std::string compilerName();
// The current time in UTC, ISO 8601 ("2026-12-02T21:30:00Z").
std::string utcNow();

}  // namespace dw
