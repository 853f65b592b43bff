#include "python/Arguments.h"

#include <cstdio>

namespace py = pybind11;

namespace dw::python {

std::string typeName(const py::handle& value) {
    return py::str(py::type::of(value).attr("__name__")).cast<std::string>();
}

int intArg(const py::handle& value, const std::string& name, OptionRange range, const std::string& flag) {
    const std::string expected = name + " must be an integer between " + std::to_string(range.min) + " and " +
                                 std::to_string(range.max) + (flag.empty() ? "" : " (as " + flag + ")");
    if (value.is_none() || PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
        throw py::type_error(expected + ", got " + typeName(value));
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
    if (!index) throw py::error_already_set();
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow == 0 && v == -1 && PyErr_Occurred()) throw py::error_already_set();
    if (overflow != 0) throw py::value_error(expected + ", got an integer beyond 64 bits");
    if (!range.holds(v)) throw py::value_error(expected + ", got " + std::to_string(v));
    return static_cast<int>(v);
}

double numberArg(const py::handle& value, const std::string& name, RealRange range, const std::string& flag) {
    char bound[96];
    std::snprintf(bound, sizeof bound, range.minOpen ? "above %g and at most %g" : "from %g to %g", range.min, range.max);
    const std::string expected = name + " must be a finite number " + bound + " (as " + flag + ")";
    if (value.is_none() || PyBool_Check(value.ptr()) || PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr()))
        throw py::type_error(expected + ", got " + typeName(value));
    const double v = PyFloat_AsDouble(value.ptr());
    if (v == -1.0 && PyErr_Occurred()) {
        const bool overflow = PyErr_ExceptionMatches(PyExc_OverflowError) != 0;
        PyErr_Clear();
        if (overflow) throw py::value_error(expected + ", got a number beyond a double's range");
        throw py::type_error(expected + ", got " + typeName(value));
    }
    if (!range.holds(v)) throw py::value_error(expected + ", got " + py::repr(value).cast<std::string>());
    return v;
}

std::pair<int, int> sizeArg(const py::handle& value, const std::string& name, OptionRange range, const std::string& flag) {
    if (!(py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) || py::len(value) != 2)
        throw py::type_error(name + " must be (width, height), two integers, got " +
                             (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)
                                  ? std::to_string(py::len(value)) + " items"
                                  : typeName(value)));
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(value);
    return {intArg(py::object(pair[0]), name + " width", range, flag), intArg(py::object(pair[1]), name + " height", range, flag)};
}

void requirePath(const std::optional<std::string>& path, const std::string& name) {
    if (path && path->empty()) throw py::value_error(name + " is an empty path: name a file");
}

void requireCallable(const py::object& f, const std::string& name) {
    if (!f.is_none() && !PyCallable_Check(f.ptr()))
        throw py::type_error(name + " must be a callable or None, got " + typeName(f));
}

}  // namespace dw::python
