#pragma once
// Outputs that were renamed, so an old script's --buffer says how to fix it
// (issue 22: ssao.raw is ao.raw, ssao.blurred is ao.filtered, now that every
// AO method publishes them). Knob renames are KnobRegistry::addAlias's.
#include <string>

namespace dw {

// "unknown buffer 'NAME'", plus ": renamed to 'NEW' (...)" for a renamed one.
std::string unknownBufferMessage(const std::string& name);

}  // namespace dw
