#pragma once
// Random numbers of the CPU reference that depend only on a pixel's index
// and a seed (never on which thread renders it), so a render is the same for
// any thread count: SplitMix64 (Steele et al. 2014) and its top 53 bits as a
// double in [0, 1).
#include <cstdint>

namespace dw::reference {

inline std::uint64_t mix64(std::uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

inline double unitFloat(std::uint64_t z) { return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0); }

}  // namespace dw::reference
