#include "renderer/scene/CameraCheck.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "renderer/io/FloatCheck.h"

namespace dw {

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}
float maxAbs(const glm::vec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

}  // namespace

bool upIsUsable(const Camera& c) {
    const glm::dvec3 d = glm::dvec3(c.target) - glm::dvec3(c.position);
    const glm::dvec3 u(c.up);
    const double ld = glm::length(d), lu = glm::length(u);
    if (!(lu > 0.0) || !(ld > 0.0)) return false;
    return glm::length(glm::cross(d / ld, u / lu)) >= kMinUpAngleSin;
}

std::optional<CameraProblem> findCameraProblem(const Camera& c, float sceneExtent) {
    if (!finite(c.position)) return CameraProblem{"pos", "is not finite"};
    if (!finite(c.target)) return CameraProblem{"look-at", "is not finite"};
    if (!finite(c.up)) return CameraProblem{"up", "is not finite"};
    if (!(c.fovYDegrees > 0.0f && c.fovYDegrees < 179.0f))
        return CameraProblem{"fov", "must be in (0, 179) degrees, got " + shortNumber(c.fovYDegrees)};
    // Narrower, the projection's scale (1 / tan(fov / 2)) leaves float
    // precision and the frame breaks into blocks or goes black.
    if (c.fovYDegrees < 1e-3f)
        return CameraProblem{"fov", "must be at least 0.001 degrees (narrower leaves 32-bit float precision), got " +
                                        shortNumber(c.fovYDegrees)};
    if (!(c.nearPlane > 0.0f)) return CameraProblem{"near", "must be greater than 0, got " + shortNumber(c.nearPlane)};
    if (c.nearPlane < FLT_MIN)
        return CameraProblem{"near", shortNumber(c.nearPlane) +
                                         " is below the smallest normal 32-bit float (1.2e-38): depth would not be representable"};
    if (!std::isfinite(c.farPlane)) return CameraProblem{"far", "is not finite"};
    if (!(c.farPlane > c.nearPlane))
        return CameraProblem{"far", "must be greater than near (" + shortNumber(c.nearPlane) + "), got " +
                                        shortNumber(c.farPlane)};
    const double distance = glm::length(glm::dvec3(c.target) - glm::dvec3(c.position));
    const double scale = std::max({static_cast<double>(sceneExtent), static_cast<double>(maxAbs(c.position)),
                                   static_cast<double>(maxAbs(c.target))});
    // Also a floor where the float direction itself would underflow.
    if (!(distance > kMinViewDistance * scale) || !(distance * distance > static_cast<double>(FLT_MIN)))
        return CameraProblem{"look-at", "must differ from pos (they are " + shortNumber(distance) +
                                            " apart, at a scale of " + shortNumber(scale) + ")"};
    if (!(glm::length(glm::dvec3(c.up)) > 0.0)) return CameraProblem{"up", "must not be zero"};
    if (!upIsUsable(c)) return CameraProblem{"up", "is parallel to the view direction (look-at - pos)"};
    if (!finite(c.view())) return CameraProblem{"pos", "gives a view matrix that is not finite in 32-bit floats"};
    for (float aspect : {1e-3f, 1.0f, 1e3f})
        if (!finite(c.projection(aspect)))
            return CameraProblem{"near", "gives a projection matrix that is not finite in 32-bit floats (near " +
                                             shortNumber(c.nearPlane) + ", far " + shortNumber(c.farPlane) + ")"};
    return std::nullopt;
}

}  // namespace dw
