#pragma once
// The Python module deferred_workbench, one area a file: each function
// defines its area's classes and functions on the module. python/Module.cpp
// calls them in the order below (the order the module lists them in).
// Images are numpy arrays (python/Arrays.h), records dicts (python/Records.h);
// the GIL is released while frames render, shaders compile and the CPU
// reference traces.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // std::optional, std::vector, std::pair arguments and results

#include "python/WorkbenchSession.h"

namespace dw::python {

using SessionClass = pybind11::class_<WorkbenchSession>;

// dw.Error (RuntimeError), dw.KnobError (ValueError), dw.ThreadError (an
// Error), and which Python exception each of the library's becomes (ErrorBindings.cpp).
void bindErrors(pybind11::module_& m);

// dw.Session: knobs, buffers, render, timings, probe, write, dump_knobs
// (SessionBindings.cpp); the other areas add their methods to the class it returns.
SessionClass bindSession(pybind11::module_& m);

// Session.record (RecordBindings.cpp).
void bindRecords(SessionClass& session);

// Session.reference: the CPU reference of the view (ReferenceBindings.cpp).
void bindReference(SessionClass& session);

// dw.bench: bench's grid in this process (BenchBindings.cpp).
void bindBench(pybind11::module_& m);

// dw.tradeoff: tradeoff's sweep in this process (TradeoffBindings.cpp).
void bindTradeoff(pybind11::module_& m);

// dw.attribute: tradeoff --attribute in this process (AttributionBindings.cpp).
void bindAttribution(pybind11::module_& m);

// dw.compare and dw.load_image (ReferenceBindings.cpp).
void bindCompare(pybind11::module_& m);

}  // namespace dw::python
