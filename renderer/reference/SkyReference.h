#pragma once
// The sky's radiance in a world direction, as shaders/sky/sky.frag computes
// it (procedural gradient with the sun disc, equirectangular or cube
// environment rotated about +Y, or the flat background colour), in double
// precision and without the sky target's half-float range. Environment
// images are sampled bilinearly at the base level (u repeats, v clamps; cube
// faces clamp at their edges).
#include <glm/glm.hpp>

#include "renderer/reference/ReferenceModel.h"
#include "renderer/scene/Scene.h"

namespace dw::reference {

class SkyReference {
public:
    SkyReference(const Scene& scene, const ReferenceModel& model);
    // `direction`: world space, unit.
    glm::dvec3 radiance(const glm::dvec3& direction) const;

private:
    glm::dvec3 procedural(const glm::dvec3& d) const;
    const Scene& scene_;
    SkyChoice kind_;
    double intensity_, rotation_;
    bool hasSun_ = false;
    glm::dvec3 sunDirection_{0.0, 1.0, 0.0}, sunColor_{0.0};
    double cosSunRadius_ = 1.0;
};

}  // namespace dw::reference
