#pragma once
// Shadow-caster culling (issue 36): which of the scene's draws can put a
// fragment into one shadow map. A CasterVolume is the map's view volume in
// absolute world space: half-spaces dot(plane.xyz, p) + plane.w >= 0 (the
// planes of a clip volume, of a hemisphere) and, for a paraboloid half, a
// sphere around the light. A draw whose world-space box lies wholly outside
// one of them has every vertex outside the clip volume the GPU clips its
// triangles against, so skipping it leaves the map bit-identical.
//
// Conservative by construction: the plane on the light's side of a map is
// never tested (a caster between the light and the fitted volume still
// casts into it, and a directional map's depth range already reaches across
// the whole scene towards the light), and a box counts as outside only when
// it is farther out than a margin of 1e-5 of its distance and size (float
// rounding on the GPU).
#include <glm/glm.hpp>
#include <vector>

namespace dw {

struct Bounds;

class CasterVolume {
public:
    // The clip volume of `worldToClip` (absolute world space to clip space,
    // x and y in [-w, w], depth in [0, w] as DepthConvention sets it):
    // left, right, bottom, top and the far plane, which is depth w, or 0 when
    // `reversed`. The near plane (the light's side) is left out.
    static CasterVolume frustum(const glm::dmat4& worldToClip, bool reversed);
    // One half of a dual-paraboloid map: the points p with
    // dot(p - apex, axis) >= 0 (the half the map's clip distance keeps) no
    // farther than `radius` from `apex` (the map's far distance). `axis` need
    // not be unit length.
    static CasterVolume hemisphere(const glm::dvec3& apex, const glm::dvec3& axis, double radius);
    // Everything: what culling switched off tests against.
    static CasterVolume everything() { return {}; }

    // False when `box` (world space) is wholly outside; an empty box is kept.
    bool mayCast(const Bounds& box) const;
    const std::vector<glm::dvec4>& planes() const { return planes_; }  // unit normals, inside positive

private:
    void addPlane(const glm::dvec4& plane);  // normalises; a degenerate plane is dropped
    std::vector<glm::dvec4> planes_;
    glm::dvec3 centre_{0.0};
    double radius_ = -1.0;  // negative: no sphere
};

}  // namespace dw
