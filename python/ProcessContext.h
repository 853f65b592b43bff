#pragma once
// The Python module's one OpenGL context: a headless EGL context
// (headless/HeadlessGlContext) made on the first Session's thread and kept
// until the process exits (never torn down under Python's finalisation).
// A context is current on one thread only: every GL call of the module runs
// on `thread`.
#include <string>
#include <thread>

#include "headless/HeadlessGlContext.h"

namespace dw {

struct ProcessContext {
    HeadlessGlContext* context = nullptr;
    std::thread::id thread;  // the thread that made it
};

// The process's context, made (and made current) on the first call; throws
// GlUnsupportedError when no OpenGL 4.5 context can be made.
ProcessContext& processContext();

// A thread's id as text, for messages.
std::string describeThread(std::thread::id id);

}  // namespace dw
