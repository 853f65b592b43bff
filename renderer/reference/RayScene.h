#pragma once
// The scene's triangles for ray queries on Intel Embree 3 (DESIGN.md "The
// measuring half"): one Embree triangle geometry per mesh instance, built
// once, with the instance's vertices kept in double precision beside it so a
// hit is recomputed exactly from its triangle and barycentrics (Embree's rays
// and hit distances are single precision).
//
// Coordinates are relative to `origin`. The reference builds one ray scene
// per scene with its origin at the centre of the scene's bounds
// (sceneCentre), shared by every camera of a run (RaySceneCache): the floats
// Embree holds are then at most the scene's radius, and rays from any camera
// start at the camera's origin-relative position. A ray scene built with the
// origin at one camera's position (as every reference was before issue 33,
// and as SsaoDefinition still builds its own) is the per-camera frame of the
// GPU's camera-relative transforms (renderer/graph/Pipeline.cpp).
//
// Self-contained: it keeps copies of what its queries read (the scene's
// materials, the meshes' indices, the base-colour images of alpha-masked
// materials), so it outlives the Scene it was built from and serves any
// Scene of the same content (sceneGeometryKey, ReferenceCache.h).
//
// What a ray sees, as the rasteriser sees it:
// - alpha-masked materials (glTF MASK) are cut out where the base colour's
//   alpha (factor x vertex colour x texture, bilinear at the base level) is
//   below the cutoff, for every kind of ray;
// - primary rays (Visibility::Camera) skip the back faces of single-sided
//   materials (the GPU culls them); secondary rays (shadow, AO) stop at any
//   face.
// - blended materials (glTF BLEND) are seen by primary rays only: they cast
//   no shadow and occlude no AO (on the GPU they are in neither the shadow
//   maps nor the G-buffer); ReferenceRenderer composites them in exact order.
// Errors: Error when Embree cannot create its device or build the scene.
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "renderer/scene/Scene.h"

namespace dw::reference {

// A mesh instance's vertices, transformed to `origin`-relative world space in
// double precision; normals by the inverse transpose, tangents by the matrix
// (their w, the bitangent sign, times the determinant's sign).
struct InstanceGeometry {
    int material = 0;
    bool mirrored = false;  // negative determinant: the GPU swaps the front-face winding
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    std::vector<glm::dvec4> tangents;
    std::vector<glm::dvec2> uv0, uv1;
    std::vector<glm::dvec4> colors;
    const std::vector<std::uint32_t>* indices = nullptr;  // the mesh's (kept by the RayScene), three per triangle
};

// Camera: primary rays. Secondary: AO rays. Shadow: rays towards a light.
enum class Visibility { Camera, Secondary, Shadow };

struct RayHit {
    bool hit = false;
    double t = 0.0;   // along the ray's direction as given (not normalised)
    int instance = -1;
    int triangle = -1;
    double u = 0.0, v = 0.0;  // barycentrics of vertices 1 and 2
};

class RayScene {
public:
    // `origin`: world-space point the coordinates are relative to (sceneCentre
    // for a ray scene shared across cameras; a camera's position for its own).
    RayScene(const Scene& scene, const glm::dvec3& origin);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Nearest hit with t in [tNear, tFar]; `org` is origin-relative.
    RayHit intersect(const glm::dvec3& org, const glm::dvec3& dir, double tNear, double tFar, Visibility v) const;
    // Whether anything lies on the ray with t in [tNear, tFar]. `blendedCastShadows`:
    // blended surfaces stop it too, as the GPU's shadows.blended_casters draws
    // them into the maps (otherwise they cast no shadow).
    bool occluded(const glm::dvec3& org, const glm::dvec3& dir, double tNear, double tFar,
                  bool blendedCastShadows = false) const;

    // The centre of the scene's bounds (world space; 0 for an empty scene).
    static glm::dvec3 sceneCentre(const Scene& scene);
    // RayScenes built in this process so far (for tests: a sweep of N cameras builds one).
    static long long buildCount();

    const std::vector<Material>& materials() const { return materials_; }
    const glm::dvec3& origin() const { return origin_; }
    const std::vector<InstanceGeometry>& instances() const { return instances_; }
    // The triangle's three vertex indices.
    glm::uvec3 triangle(int instance, int triangle) const;
    // Length scale of the scene (its bounding radius, at least 1e-30): ray offsets follow it.
    double sceneRadius() const { return sceneRadius_; }
    size_t triangleCount() const { return triangles_; }

    // Whether an alpha-masked material cuts the point out (used by Embree's filters).
    bool cutOut(int instance, int triangle, double u, double v) const;
    // Whether the instance's material is blended (AlphaMode::Blend).
    bool blended(int instance) const;
    // Whether the ray direction meets the triangle's back face (origin-relative geometric normal by winding).
    bool backFacing(int instance, int triangle, const glm::dvec3& dir) const;

private:
    struct Embree;
    void addInstance(const Scene& scene, const MeshInstance& inst);
    std::vector<Material> materials_;
    std::vector<Image> maskImages_;  // by image index: the base colours of MASK materials (others empty)
    std::vector<std::vector<std::uint32_t>> indices_;  // by mesh
    glm::dvec3 origin_;
    double sceneRadius_ = 1.0;
    size_t triangles_ = 0;
    std::vector<InstanceGeometry> instances_;
    std::unique_ptr<Embree> embree_;
};

}  // namespace dw::reference
