#include "app/FrameWait.h"

#include <algorithm>

namespace dw {

double FrameWait::timeout(const FrameActivity& a) {
    if (a.input) settle_ = kSettleFrames;
    if (a.scripted || a.rendered || a.busy || a.held) return 0.0;
    if (settle_ > 0) {
        --settle_;
        return 0.0;
    }
    double t = kIdleSeconds;
    if (a.background) t = std::min(t, kBackgroundSeconds);
    if (a.typing) t = std::min(t, kBlinkSeconds);
    // The toast goes when its time is up, not at the next event.
    if (a.toastLeft >= 0.0) t = std::min(t, a.toastLeft + 0.02);
    return t;
}

}  // namespace dw
