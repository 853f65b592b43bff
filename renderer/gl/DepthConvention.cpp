#include "renderer/gl/DepthConvention.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace dw {

glm::dmat4 DepthConvention::perspective(double fovY, double aspect, double near, double far) const {
    // GLM's zero-to-one projection; reversed Z is the same matrix with the
    // planes swapped (depth 1 at `near`, 0 at `far`).
    return reversed() ? glm::perspectiveRH_ZO(fovY, aspect, far, near) : glm::perspectiveRH_ZO(fovY, aspect, near, far);
}

glm::dmat4 DepthConvention::orthographic(double left, double right, double bottom, double top, double near,
                                         double far) const {
    return reversed() ? glm::orthoRH_ZO(left, right, bottom, top, far, near)
                      : glm::orthoRH_ZO(left, right, bottom, top, near, far);
}

double DepthConvention::perspectiveDepth(double distance, double near, double far) const {
    // Conventional: f (d - n) / (d (f - n)); reversed: n (f - d) / (d (f - n)).
    return reversed() ? near * (far - distance) / (distance * (far - near))
                      : far * (distance - near) / (distance * (far - near));
}

void DepthConvention::applyClipControl() { glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); }

}  // namespace dw
