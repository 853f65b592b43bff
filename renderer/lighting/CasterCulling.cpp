#include "renderer/lighting/CasterCulling.h"

#include <algorithm>
#include <cmath>

#include "renderer/scene/Mesh.h"

namespace dw {

namespace {

constexpr double kMargin = 1e-5;  // relative to a box's distance and size

glm::dvec4 row(const glm::dmat4& m, int r) { return {m[0][r], m[1][r], m[2][r], m[3][r]}; }

}  // namespace

void CasterVolume::addPlane(const glm::dvec4& plane) {
    const double n = glm::length(glm::dvec3(plane));
    if (!(n > 0.0) || !std::isfinite(n)) return;
    planes_.push_back(plane / n);
}

CasterVolume CasterVolume::frustum(const glm::dmat4& worldToClip, bool reversed) {
    CasterVolume v;
    const glm::dvec4 x = row(worldToClip, 0), y = row(worldToClip, 1), z = row(worldToClip, 2), w = row(worldToClip, 3);
    v.addPlane(w + x);
    v.addPlane(w - x);
    v.addPlane(w + y);
    v.addPlane(w - y);
    // Depth is in [0, w]: the far plane is depth <= w, or depth >= 0 reversed.
    v.addPlane(reversed ? z : w - z);
    return v;
}

CasterVolume CasterVolume::hemisphere(const glm::dvec3& apex, const glm::dvec3& axis, double radius) {
    CasterVolume v;
    v.addPlane(glm::dvec4(axis, -glm::dot(axis, apex)));
    v.centre_ = apex;
    v.radius_ = radius;
    return v;
}

bool CasterVolume::mayCast(const Bounds& box) const {
    if (box.empty()) return true;
    const glm::dvec3 lo(box.min), hi(box.max);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double size = glm::length(hi - lo);
    for (const glm::dvec4& p : planes_) {
        // The corner farthest along the plane's normal.
        const glm::dvec3 corner(p.x >= 0.0 ? hi.x : lo.x, p.y >= 0.0 ? hi.y : lo.y, p.z >= 0.0 ? hi.z : lo.z);
        const double margin = kMargin * (std::fabs(glm::dot(glm::dvec3(p), centre)) + std::fabs(p.w) + size);
        if (glm::dot(glm::dvec3(p), corner) + p.w < -margin) return false;
    }
    if (radius_ >= 0.0) {
        const glm::dvec3 nearest = glm::clamp(centre_, lo, hi);
        const double margin = kMargin * (radius_ + glm::length(centre_ - centre) + size);
        if (glm::length(nearest - centre_) > radius_ + margin) return false;
    }
    return true;
}

}  // namespace dw
