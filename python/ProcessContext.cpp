#include "python/ProcessContext.h"

#include <sstream>

namespace dw {

ProcessContext& processContext() {
    static ProcessContext pc;
    if (!pc.context) {
        pc.context = HeadlessGlContext::create().release();
        pc.thread = std::this_thread::get_id();
    }
    return pc;
}

std::string describeThread(std::thread::id id) {
    std::ostringstream s;
    s << id;
    return s.str();
}

}  // namespace dw
