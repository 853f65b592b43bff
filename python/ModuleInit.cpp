#include "python/ModuleInit.h"

#include <cctype>

#include "renderer/record/BuildInfo.h"

namespace py = pybind11;

namespace dw {

namespace {

std::string buildField(const std::string& key) {
    for (const auto& [k, v] : buildFields())
        if (k == key) return v;
    return "unknown";
}

}  // namespace

void requireNumpy() {
    try {
        py::module_::import("numpy");
    } catch (py::error_already_set& e) {
        if (!e.matches(PyExc_ImportError)) throw;
        std::string why = py::str(e.value()).cast<std::string>();
        const std::string python = py::module_::import("sys").attr("executable").cast<std::string>();
        throw py::import_error("deferred_workbench needs numpy, which " + (python.empty() ? "this Python" : python) +
                               " cannot import (" + why +
                               "); install it for that interpreter (Debian: python3-numpy for /usr/bin/python3)");
    }
}

std::string moduleCommit() { return buildField("commit"); }

std::string moduleVersion() {
    const std::string version = buildField("version"), commit = moduleCommit();
    if (commit.empty() || commit == "unknown") return version;
    std::string local;
    for (const char c : commit) local += std::isalnum(static_cast<unsigned char>(c)) ? c : '.';
    return version + "+" + local;
}

}  // namespace dw
