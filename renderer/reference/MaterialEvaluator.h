#pragma once
// A material's Blinn-Phong terms at a ray hit, in double precision: the CPU
// side of shaders/common/material_eval.glsl (glTF metallic-roughness and
// specular-glossiness mapped to diffuse, specular colour and exponent, normal
// maps, vertex colours, emission, baked occlusion), with the G-buffer's
// storage ranges applied as the deferred pipeline applies them (diffuse and
// specular colour in [0, 1], exponent in [1, 2048], emission up to 65000) but
// none of its quantisation. Textures: TextureSampler (bilinear, base level).
#include <glm/glm.hpp>

#include "renderer/reference/RayScene.h"

namespace dw::reference {

struct SurfaceSample {
    glm::dvec3 position;         // world space relative to the RayScene's origin, recomputed from the triangle in double
    glm::dvec3 geometricNormal;  // unit, on the side the ray came from
    glm::dvec3 normal;           // unit shading normal (interpolated, normal-mapped, facing the viewer on back faces)
    glm::dvec3 diffuse;
    glm::dvec3 specular;
    double exponent = 1.0;
    glm::dvec3 emissive{0.0};
    double occlusion = 1.0;  // baked ambient accessibility (occlusionTexture), 1 without one
    double alpha = 1.0;      // base colour alpha (factor x vertex colour x texture), for blended materials
};

// `dir` is the incoming ray's direction (any length). `scene`: the materials and
// images, the content `rays` was built from.
SurfaceSample evaluateSurface(const Scene& scene, const RayScene& rays, const RayHit& hit, const glm::dvec3& org,
                              const glm::dvec3& dir);

}  // namespace dw::reference
