// Records: Session.record, and the record helpers bench and tradeoff use (Records.h).
#include "python/Bindings.h"
#include "python/Arguments.h"
#include "python/Records.h"

namespace py = pybind11;

namespace dw::python {

py::object recordObject(const ExperimentRecord& record) {
    return py::module_::import("json").attr("loads")(record.json());
}

std::optional<std::string> recordPath(const std::string& function, std::optional<std::string> json,
                                      std::optional<std::string> record) {
    if (json && record && *json != *record)
        throw py::value_error(function + ": record='" + *record + "' and json='" + *json +
                              "' name two files: give one (json= is record='s older name)");
    return record ? record : json;
}

namespace {

py::object writeRecord(WorkbenchSession& s, const std::string& path) {
    requirePath(path, "record: path");
    ExperimentRecord r;
    {
        py::gil_scoped_release release;
        r = s.record();
        r.write(path);
    }
    return recordObject(r);
}

}  // namespace

void bindRecords(SessionClass& session) {
    session.def("record", &writeRecord, py::arg("path"),
                "Writes the experiment record of the last render() (its buffer, frames, warm-up; the knobs as they are\n"
                "now) to `path`, as render --record does, and returns it as a dict.");
}

}  // namespace dw::python
