#pragma once
// A unit vector from a direction of any length a 32-bit float can hold.
// The direction is computed and normalised in double: a face of a box 1e-12
// across has a cross product of 1e-24, whose squared length (1e-48) is below
// the smallest float, so glm::normalize in float divides by 0 (NaN normals),
// and a side of 1e30 overflows the same way. In double, products and squares
// of any two floats stay in range (1e-90 .. 1e154).
#include <cmath>
#include <glm/glm.hpp>

namespace dw {

// `v` / |v|, or `fallback` when v is zero or not finite.
inline glm::vec3 unitVector(const glm::dvec3& v, const glm::vec3& fallback) {
    const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(len > 0.0) || !std::isfinite(len)) return fallback;
    return glm::vec3(v / len);
}

}  // namespace dw
