#pragma once
// The view frustum's six planes (Gribb & Hartmann) from a world-to-clip
// matrix, normalised, in double precision (a scene far from the origin);
// clip depth in [0, 1] (DepthConvention), so the depth planes are z >= 0 and
// z <= w. What the light table and the passes that cull by view test against.
#include <array>
#include <glm/glm.hpp>

namespace dw {

class ViewFrustum {
public:
    explicit ViewFrustum(const glm::dmat4& worldToClip);
    // Whether the sphere (world centre, radius) lies wholly outside one plane.
    bool sphereOutside(const glm::dvec3& centre, double radius) const;

private:
    std::array<glm::dvec4, 6> planes_;
};

}  // namespace dw
