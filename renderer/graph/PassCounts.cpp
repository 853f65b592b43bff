#include "renderer/graph/PassCounts.h"

namespace dw {

namespace {
const char* const kNames[PassCounts::kCount] = {"fragments", "samples", "primitives", "vertices", "compute", "bytes"};
}

const char* PassCounts::name(int i) { return i >= 0 && i < kCount ? kNames[i] : "?"; }

int PassCounts::index(const std::string& name) {
    for (int i = 0; i < kCount; ++i)
        if (name == kNames[i]) return i;
    return -1;
}

bool PassCounts::measured() const {
    for (auto x : v)
        if (x >= 0) return true;
    return false;
}

void PassCounts::add(const PassCounts& other) {
    for (size_t i = 0; i < v.size(); ++i)
        if (other.v[i] >= 0) v[i] = (v[i] < 0 ? 0 : v[i]) + other.v[i];
}

}  // namespace dw
