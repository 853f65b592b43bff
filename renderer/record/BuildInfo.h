#pragma once
// What built this binary, for the experiment records: the project version,
// the git commit at configure time, the compiler, the build type and the
// compiler flags of that build type (CMake puts them on BuildInfo.cpp).
#include <string>
#include <utility>
#include <vector>

namespace dw {

// version, commit, compiler, build_type, cxx_flags (in that order).
std::vector<std::pair<std::string, std::string>> buildFields();

}  // namespace dw
