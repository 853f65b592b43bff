#pragma once
// A 32-bit integer hash (Wellons' "lowbias32") for deterministic procedural
// values: textures, flame particles, SSAO kernels. A pure function of its
// input, so every frame and every machine gets the same numbers (DESIGN.md,
// "Deterministic captures": no RNG state, no wall clock).
#include <cstdint>

namespace dw {

inline std::uint32_t hashU32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// A number in [0, 1) from the hash's low 24 bits.
inline float hashToUnit(std::uint32_t x) { return static_cast<float>(hashU32(x) & 0xffffffu) / 16777216.0f; }

}  // namespace dw
