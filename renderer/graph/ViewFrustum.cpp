#include "renderer/graph/ViewFrustum.h"

namespace dw {

ViewFrustum::ViewFrustum(const glm::dmat4& m) {
    auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    planes_ = {row(3) + row(0), row(3) - row(0), row(3) + row(1), row(3) - row(1), row(2), row(3) - row(2)};
    for (auto& plane : planes_) plane /= glm::length(glm::dvec3(plane));
}

bool ViewFrustum::sphereOutside(const glm::dvec3& c, double r) const {
    for (const auto& p : planes_)
        if (glm::dot(glm::dvec3(p), c) + p.w < -r) return true;
    return false;
}

}  // namespace dw
