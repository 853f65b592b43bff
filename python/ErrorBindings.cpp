// The module's exceptions: the library's dw::Error and the kinds the
// session throws, as Python exceptions.
#include "python/Bindings.h"

namespace py = pybind11;

namespace dw::python {

void bindErrors(py::module_& m) {
    static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
    static py::exception<KnobError> knobError(m, "KnobError", PyExc_ValueError);
    static py::exception<WrongThreadError> threadError(m, "ThreadError", error.ptr());
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const KnobError& e) {
            knobError(e.what());
        } catch (const UnknownBufferError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const WrongThreadError& e) {
            threadError(e.what());
        } catch (const Error& e) {
            error(e.what());
        }
    });
}

}  // namespace dw::python
