#include "renderer/graph/RenamedOutputs.h"

#include <utility>

namespace dw {

std::string unknownBufferMessage(const std::string& name) {
    static const std::pair<const char*, const char*> kRenamed[] = {{"ssao.raw", "ao.raw"}, {"ssao.blurred", "ao.filtered"}};
    for (const auto& [was, is] : kRenamed)
        if (name == was)
            return "unknown buffer '" + name + "': renamed to '" + is +
                   "' (issue 22: every AO method, ao.method, publishes ao.raw and ao.filtered)";
    return "unknown buffer '" + name + "'";
}

}  // namespace dw
