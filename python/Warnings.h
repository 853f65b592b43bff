#pragma once
// The module's warnings: the lines the CLI prints as warnings (a loader's,
// AOV's cost, lost transparent fragments) reach Python as warnings.warn.
#include <string>

namespace dw::python {

// `line` as a RuntimeWarning (warnings.warn); with the warnings filter set to
// "error" it is raised (pybind11::error_already_set). Needs the GIL.
void warnPython(const std::string& line);

}  // namespace dw::python
