#include "python/Warnings.h"

#include <pybind11/pybind11.h>

namespace dw::python {

void warnPython(const std::string& line) {
    if (PyErr_WarnEx(PyExc_RuntimeWarning, line.c_str(), 1) != 0) throw pybind11::error_already_set();
}

}  // namespace dw::python
