#pragma once
// Experiment records in Python: a record is the dict of the JSON it writes
// (docs/records.md); bench and tradeoff take its file as record=PATH.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "renderer/record/ExperimentRecord.h"

namespace dw::python {

// A record as Python objects: the JSON it writes, read by Python's json module.
pybind11::object recordObject(const ExperimentRecord& record);

// record=PATH and json=PATH are one keyword of bench and tradeoff (the CLI's
// --record FILE and its older name --json FILE): the experiment record's
// file, or none. ValueError when the two name different files; `function`
// names the caller.
std::optional<std::string> recordPath(const std::string& function, std::optional<std::string> json,
                                      std::optional<std::string> record);

}  // namespace dw::python
