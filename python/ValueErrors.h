#pragma once
// Runs a check whose dw::Error is a bad argument and raises it as Python's
// ValueError with the CLI's message (FileError stays dw.Error, KnobError
// dw.KnobError): dw.tradeoff's and dw.attribute's option checks.
#include <pybind11/pybind11.h>

#include "python/WorkbenchSession.h"
#include "renderer/Error.h"

namespace dw::python {

template <typename F>
auto asValueError(F&& f) {
    try {
        return f();
    } catch (const FileError&) {
        throw;
    } catch (const KnobError&) {
        throw;
    } catch (const Error& e) {
        throw pybind11::value_error(e.what());
    }
}

}  // namespace dw::python
