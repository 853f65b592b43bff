#include "renderer/record/BuildInfo.h"

#include "renderer/record/HostInfo.h"

namespace dw {

std::vector<std::pair<std::string, std::string>> buildFields() {
    std::vector<std::pair<std::string, std::string>> f;
#ifdef DW_VERSION
    f.emplace_back("version", DW_VERSION);
#else
    f.emplace_back("version", "unknown");
#endif
#ifdef DW_GIT_COMMIT
    f.emplace_back("commit", DW_GIT_COMMIT);
#else
    f.emplace_back("commit", "unknown");
#endif
    f.emplace_back("compiler", compilerName());
#ifdef DW_BUILD_TYPE
    f.emplace_back("build_type", DW_BUILD_TYPE);
#endif
#ifdef DW_CXX_FLAGS
    f.emplace_back("cxx_flags", DW_CXX_FLAGS);
#endif
    return f;
}

}  // namespace dw
