#include "python/ReferenceTrace.h"

#include <chrono>
#include <exception>
#include <future>
#include <thread>

#include "python/Arguments.h"
#include "renderer/OptionLimits.h"

namespace py = pybind11;

namespace dw::python {

ReferenceOptions referenceOptions(const std::string& function, const py::handle& aoRays, const py::handle& seed,
                                  const py::handle& threads, bool cache, const std::optional<std::string>& cacheDir) {
    ReferenceOptions o;
    o.aoRays = intArg(aoRays, function + ": ao_rays", limits::kAoRays, "reference --ao-rays");
    o.seed = intArg(seed, function + ": seed", limits::kSeed, "reference --seed");
    o.threads = intArg(threads, function + ": threads", limits::kReferenceThreads, "reference --threads; 0: every core");
    o.useCache = cache;
    o.cacheDirectory = cacheDir.value_or("");
    return o;
}

reference::ReferenceImages traceReference(const py::object& progressFn,
                                          const std::function<reference::ReferenceImages(reference::ReferenceProgress*)>& trace) {
    reference::ReferenceProgress progress;
    reference::ReferenceImages images;
    std::exception_ptr failure;
    bool raised = false;
    {
        py::gil_scoped_release release;
        std::promise<void> finished;
        std::future<void> done = finished.get_future();
        std::thread worker([&] {
            try {
                images = trace(&progress);
            } catch (...) {
                failure = std::current_exception();
            }
            finished.set_value();
        });
        while (done.wait_for(std::chrono::milliseconds(200)) != std::future_status::ready) {
            py::gil_scoped_acquire acquire;
            if (raised) continue;
            if (PyErr_CheckSignals() != 0) {
                raised = true;
            } else if (!progressFn.is_none()) {
                try {
                    progressFn(progress.fraction());
                } catch (py::error_already_set& e) {
                    e.restore();
                    raised = true;
                }
            }
            if (raised) progress.cancel.store(true);
        }
        worker.join();
    }
    if (raised) throw py::error_already_set();
    if (failure) std::rethrow_exception(failure);
    if (!progressFn.is_none()) progressFn(1.0);
    return images;
}

}  // namespace dw::python
