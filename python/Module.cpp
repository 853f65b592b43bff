// The Python module deferred_workbench (pybind11): what it sets at import,
// then each area's bindings (python/Bindings.h lists them; one file an area).
// docs/python.md says how to use it.
#include <pybind11/pybind11.h>

#include "python/Bindings.h"
#include "python/ModuleInit.h"

namespace py = pybind11;

PYBIND11_MODULE(deferred_workbench, m) {
    using namespace dw;
    m.doc() = "Deferred Workbench: render a scene headless and read any named output as a numpy array";
    requireNumpy();  // fail at import, not at the first render
    m.attr("__version__") = moduleVersion();
    m.attr("__commit__") = moduleCommit();

    python::bindErrors(m);
    python::SessionClass session = python::bindSession(m);
    python::bindRecords(session);
    python::bindReference(session);
    python::bindBench(m);
    python::bindTradeoff(m);
    python::bindAttribution(m);
    python::bindCompare(m);
}
