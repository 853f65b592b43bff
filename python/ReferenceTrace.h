#pragma once
// The CPU reference from Python: its arguments (as `reference`'s flags) and
// the trace on a worker thread, the GIL released, Ctrl-C and progress= seen
// while it runs. Session.render (a reference output) and Session.reference both trace through here.
#include <pybind11/pybind11.h>

#include <functional>
#include <optional>
#include <string>

#include "python/WorkbenchSession.h"

namespace dw::python {

// The CPU reference's options (reference's --ao-rays, --seed, --threads,
// --no-cache, --cache-dir); `function` names the caller in the messages
// (intArg's TypeError and ValueError).
ReferenceOptions referenceOptions(const std::string& function, const pybind11::handle& aoRays,
                                  const pybind11::handle& seed, const pybind11::handle& threads, bool cache,
                                  const std::optional<std::string>& cacheDir);

// Traces the CPU reference (`trace`, CPU only) on a worker thread while this
// one waits with the GIL released; every 0.2 s it takes the GIL to see
// Ctrl-C and to call progress(fraction done). KeyboardInterrupt, or what
// progress raised, cancels the trace and is raised; progress(1.0) last.
reference::ReferenceImages traceReference(
    const pybind11::object& progressFn,
    const std::function<reference::ReferenceImages(reference::ReferenceProgress*)>& trace);

}  // namespace dw::python
