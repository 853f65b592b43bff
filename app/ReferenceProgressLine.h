#pragma once
// A CPU reference traced on a worker thread while the calling thread reports
// its progress on stderr, as `reference` and `render --buffer reference.*`
// show it: a line rewritten in place on a terminal ("reference: 42.0% of
// 64x36, 1.2 s (Ctrl+C cancels)"), a line each 10% otherwise; nothing when
// `quiet`. Ctrl+C (SIGINT) or SIGTERM sets the progress's cancel flag, and
// the trace's ReferenceCancelled is rethrown here (as is anything it threw).
#include <functional>

#include "renderer/reference/ReferenceRenderer.h"

namespace dw {

// `trace` runs on the worker with the progress it must count into;
// `width` x `height` only label the line.
void traceWithProgressLine(const std::function<void(reference::ReferenceProgress*)>& trace, int width, int height,
                           bool quiet);

}  // namespace dw
