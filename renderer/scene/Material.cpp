#include "renderer/scene/Material.h"

#include <cmath>

namespace dw {

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv, with
// R = [cos sin; -sin cos] (the extension's README, "Overview").
glm::vec3 TextureMapping::row(int r) const {
    const float c = std::cos(rotation), s = std::sin(rotation);
    if (r == 0) return {c * scale.x, s * scale.y, offset.x};
    return {-s * scale.x, c * scale.y, offset.y};
}

}  // namespace dw
