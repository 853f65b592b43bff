#include "app/ReferenceProgressLine.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <thread>

namespace dw {

namespace {

reference::ReferenceProgress* gProgress = nullptr;

extern "C" void cancelOnSignal(int) {
    if (gProgress) gProgress->cancel.store(true);
}

}  // namespace

void traceWithProgressLine(const std::function<void(reference::ReferenceProgress*)>& trace, int width, int height,
                           bool quiet) {
    reference::ReferenceProgress progress;
    gProgress = &progress;
    struct sigaction action{}, oldInt{}, oldTerm{};
    action.sa_handler = cancelOnSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &oldInt);
    sigaction(SIGTERM, &action, &oldTerm);
    std::exception_ptr failure;
    std::atomic<bool> done{false};
    std::thread worker([&] {
        try {
            trace(&progress);
        } catch (...) {
            failure = std::current_exception();
        }
        done = true;
    });
    const bool tty = isatty(STDERR_FILENO) != 0;
    const auto start = std::chrono::steady_clock::now();
    int lastDecile = 0;
    while (!done.load()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        if (quiet || done.load()) continue;
        const double f = progress.fraction();
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (tty) {
            std::fprintf(stderr, "\rreference: %5.1f%% of %dx%d, %.1f s (Ctrl+C cancels)", 100.0 * f, width, height,
                         elapsed);
        } else if (static_cast<int>(f * 10.0) > lastDecile) {
            lastDecile = static_cast<int>(f * 10.0);
            std::fprintf(stderr, "reference: %d%% of %dx%d, %.1f s\n", lastDecile * 10, width, height, elapsed);
        }
    }
    worker.join();
    if (tty && !quiet) std::fprintf(stderr, "\n");
    sigaction(SIGINT, &oldInt, nullptr);
    sigaction(SIGTERM, &oldTerm, nullptr);
    gProgress = nullptr;
    if (failure) std::rethrow_exception(failure);
}

}  // namespace dw
