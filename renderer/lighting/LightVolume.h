#pragma once
// Light extents and the meshes that bound them (seed 001 section 2.2, seed 000
// section 3.2.1). The radius is where I_max * att(d) falls to the threshold
// (seed 001 eq. 1); the volume meshes circumscribe (never inscribe) the lit
// region, so the stencil test cannot cut off lit pixels.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "renderer/scene/Light.h"

namespace dw {

// Distance at which maxIntensity / (c + l d + q d^2) == threshold. Stable for
// q = 0 (linear only) and tiny q; 0 when the light never exceeds the threshold;
// +infinity when the attenuation never falls (constant only).
double solveLightRadius(const Attenuation& att, double maxIntensity, double threshold);

// The sphere volume meshes: the icosahedron subdivided 0 to 3 times (unitSphereVolume).
constexpr int kMaxSphereSubdivisions = 3;
constexpr int kDefaultSphereSubdivisions = 0;  // fastest on llvmpipe (docs/bench.md)

enum class VolumeShape { Culled, Sphere, Cone, FullScreen };

struct LightVolume {
    VolumeShape shape = VolumeShape::Culled;
    double radius = 0.0;
    glm::mat4 transform{1.0f};  // unit volume mesh -> world
};

// Spot lights get a cone while it is smaller than the sphere (tan^2(cutoff) < 4).
LightVolume computeLightVolume(const Light& light, double threshold);

struct VolumeMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    // Whether p is inside (or on) the closed convex mesh under `transform`.
    bool contains(const glm::mat4& transform, const glm::vec3& p, float epsilon = 1e-4f) const;
};

// The lights whose volume (as computeLightVolume builds it for `threshold`,
// the mesh the stencil test rasterises) contains the world point `p`: the
// point and spot lights a volume strategy evaluates there. Enabled lights
// only; directional lights (everywhere) are not listed. Indices into
// scene.lights, in order.
// `sphereSubdivisions`: the sphere mesh in use (lighting.volume_subdivisions).
std::vector<int> lightsCovering(const std::vector<Light>& lights, const glm::vec3& p, double threshold,
                                int sphereSubdivisions = kDefaultSphereSubdivisions);

// Icosphere whose faces lie outside the unit sphere (inradius 1): the
// icosahedron subdivided `subdivisions` times (0 to kMaxSphereSubdivisions),
// 20 * 4^k faces. Fewer faces cost less vertex work per light; their
// vertices reach further out (circumradius 1.259 at k = 0, 1.071 at 1,
// 1.018 at 2, 1.005 at 3), so the stencil marks a few more pixels that the
// shader's in-radius test then rejects. The image is the same at every k.
// The knob lighting.volume_subdivisions picks it.
const VolumeMesh& unitSphereVolume(int subdivisions = kDefaultSphereSubdivisions);
// Apex at the origin, axis +Z, height 1, enclosing the circular cone of base radius 1.
const VolumeMesh& unitConeVolume();

}  // namespace dw
