#include "renderer/scene/Mesh.h"

#include <cmath>

namespace dw {

Bounds Bounds::transformed(const glm::mat4& m) const {
    Bounds out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 c((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
        out.add(glm::vec3(m * glm::vec4(c, 1.0f)));
    }
    return out;
}

double sceneLengthUnit(const Bounds& bounds) {
    const double r = bounds.empty() ? 0.0 : static_cast<double>(bounds.radius());
    if (!(r > 0.0) || !std::isfinite(r)) return 1.0;
    return std::pow(10.0, std::round(std::log10(r / 10.0)));
}

void Mesh::computeBounds() {
    bounds = Bounds{};
    for (const auto& v : vertices) bounds.add(v.position);
}

}  // namespace dw
