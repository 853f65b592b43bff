#pragma once
// The Python module's argument checks: each Python argument held to the CLI
// option it stands for (its range in renderer/OptionLimits.h, its flag named
// in the message). A value of the wrong type is TypeError, one out of range
// ValueError, both naming the argument (`name`: "function: argument").
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <utility>

#include "renderer/OptionLimits.h"

namespace dw::python {

// The name of `value`'s type ("int", "NoneType"), for messages.
std::string typeName(const pybind11::handle& value);

// An integer argument held to `range`, the range of the CLI option it stands
// for (`flag` names that option). A Python int of any size or what has
// __index__ (numpy's integers) is range-checked before it is narrowed:
// outside the range, however large, is ValueError naming the argument and the
// range. None, bool, float, str and the rest are TypeError.
int intArg(const pybind11::handle& value, const std::string& name, OptionRange range, const std::string& flag = {});

// A finite number (int or float, not bool) in `range`, the range of the CLI
// option it stands for (`flag` names it): ValueError naming the argument when
// it is NaN, infinite, too large for a double or outside the range; TypeError
// for anything that is not a number.
double numberArg(const pybind11::handle& value, const std::string& name, RealRange range, const std::string& flag);

// (width, height): a tuple or list of two integers, each in `range` (--size's).
std::pair<int, int> sizeArg(const pybind11::handle& value, const std::string& name, OptionRange range = limits::kSize,
                            const std::string& flag = {});

// A file argument: an empty path names no file (ValueError naming the argument).
void requirePath(const std::optional<std::string>& path, const std::string& name);

// A callable or None (progress=): TypeError otherwise.
void requireCallable(const pybind11::object& f, const std::string& name);

}  // namespace dw::python
