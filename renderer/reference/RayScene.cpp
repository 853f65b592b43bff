#include "renderer/reference/RayScene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include "renderer/Error.h"
#include "renderer/reference/TextureSampler.h"

namespace dw::reference {

namespace {

// Embree's context, extended (the Embree 3 way) with what the filters need.
struct QueryContext {
    RTCIntersectContext embree;
    const RayScene* scene;
    Visibility visibility;
    bool blendedCastShadows;
};

std::atomic<long long> builds{0};

void filterHits(const RTCFilterFunctionNArguments* args) {
    const auto* ctx = reinterpret_cast<const QueryContext*>(args->context);
    RTCRayN* rays = args->ray;
    RTCHitN* hits = args->hit;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const int instance = static_cast<int>(RTCHitN_geomID(hits, args->N, i));
        const int triangle = static_cast<int>(RTCHitN_primID(hits, args->N, i));
        const double u = RTCHitN_u(hits, args->N, i), v = RTCHitN_v(hits, args->N, i);
        if (ctx->scene->cutOut(instance, triangle, u, v)) {
            args->valid[i] = 0;
            continue;
        }
        // Blended surfaces cast no shadow and occlude no AO (as on the GPU,
        // where they are in neither the shadow maps nor the G-buffer).
        const bool casts = ctx->visibility == Visibility::Shadow && ctx->blendedCastShadows;
        if (ctx->visibility != Visibility::Camera && !casts && ctx->scene->blended(instance)) {
            args->valid[i] = 0;
            continue;
        }
        if (ctx->visibility == Visibility::Camera) {
            const glm::dvec3 dir(RTCRayN_dir_x(rays, args->N, i), RTCRayN_dir_y(rays, args->N, i),
                                 RTCRayN_dir_z(rays, args->N, i));
            if (ctx->scene->backFacing(instance, triangle, dir)) args->valid[i] = 0;
        }
    }
}

void throwOnError(RTCDevice device, const char* what) {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE) throw Error(std::string("Embree: ") + what + " failed (error " + std::to_string(e) + ")");
}

RTCRay makeRay(const glm::dvec3& org, const glm::dvec3& dir, double tNear, double tFar) {
    RTCRay r{};
    r.org_x = static_cast<float>(org.x);
    r.org_y = static_cast<float>(org.y);
    r.org_z = static_cast<float>(org.z);
    r.dir_x = static_cast<float>(dir.x);
    r.dir_y = static_cast<float>(dir.y);
    r.dir_z = static_cast<float>(dir.z);
    r.tnear = static_cast<float>(tNear);
    r.tfar = static_cast<float>(std::min(tFar, 3.0e38));
    r.mask = 0xFFFFFFFFu;
    r.flags = 0;
    return r;
}

}  // namespace

struct RayScene::Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Embree() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

RayScene::RayScene(const Scene& scene, const glm::dvec3& origin)
    : materials_(scene.materials), origin_(origin), embree_(std::make_unique<Embree>()) {
    ++builds;
    const Bounds b = scene.bounds();
    sceneRadius_ = std::max(b.empty() ? 1.0 : static_cast<double>(b.radius()), 1e-30);
    maskImages_.resize(scene.images.size());
    for (const Material& m : materials_)
        if (m.alphaMode == AlphaMode::Mask && m.baseColorTexture >= 0 &&
            m.baseColorTexture < static_cast<int>(scene.images.size()))
            maskImages_[m.baseColorTexture] = scene.images[m.baseColorTexture];
    indices_.reserve(scene.meshes.size());
    for (const Mesh& mesh : scene.meshes) indices_.push_back(mesh.indices);
    embree_->device = rtcNewDevice("");
    if (!embree_->device) throw Error("Embree: cannot create a device (rtcNewDevice)");
    embree_->scene = rtcNewScene(embree_->device);
    throwOnError(embree_->device, "rtcNewScene");
    rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
    instances_.reserve(scene.instances.size());
    for (const MeshInstance& inst : scene.instances) addInstance(scene, inst);
    rtcCommitScene(embree_->scene);
    throwOnError(embree_->device, "building the scene (rtcCommitScene)");
}

// The instance's vertices in double, origin-relative, and its Embree geometry.
void RayScene::addInstance(const Scene& scene, const MeshInstance& inst) {
    const Mesh& mesh = scene.meshes[inst.mesh];
    InstanceGeometry g;
    g.material = mesh.material;
    const glm::dmat4 m(inst.transform);
    const glm::dmat3 m3(m);
    const double det = glm::determinant(m3);
    g.mirrored = det < 0.0;
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(m3));
    const size_t n = mesh.vertices.size();
    g.positions.resize(n);
    g.normals.resize(n);
    g.tangents.resize(n);
    g.uv0.resize(n);
    g.uv1.resize(n);
    g.colors.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Vertex& v = mesh.vertices[i];
        g.positions[i] = glm::dvec3(m * glm::dvec4(glm::dvec3(v.position), 1.0)) - origin_;
        g.normals[i] = normalMatrix * glm::dvec3(v.normal);
        g.tangents[i] = glm::dvec4(m3 * glm::dvec3(v.tangent), v.tangent.w);
        g.uv0[i] = glm::dvec2(v.uv);
        g.uv1[i] = glm::dvec2(v.uv1);
        g.colors[i] = glm::dvec4(v.color);
    }
    g.indices = &indices_[static_cast<size_t>(inst.mesh)];

    RTCGeometry geom = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), std::max<size_t>(n, 1)));
    const size_t triangles = mesh.indices.size() / 3;
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                              3 * sizeof(unsigned), triangles));
    if (!vb || (!ib && triangles > 0)) {
        rtcReleaseGeometry(geom);
        throwOnError(embree_->device, "rtcSetNewGeometryBuffer");
        throw Error("Embree: out of memory for the scene's triangles");
    }
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) vb[3 * i + c] = static_cast<float>(g.positions[i][c]);
    for (size_t i = 0; i < triangles * 3; ++i) ib[i] = mesh.indices[i];
    const Material& mat = scene.materials[mesh.material];
    rtcSetGeometryIntersectFilterFunction(geom, filterHits);
    if (mat.alphaMode != AlphaMode::Opaque) rtcSetGeometryOccludedFilterFunction(geom, filterHits);
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(embree_->scene, geom);
    rtcReleaseGeometry(geom);
    if (id != instances_.size()) throw Error("Embree: unexpected geometry id");
    triangles_ += triangles;
    instances_.push_back(std::move(g));
}

glm::dvec3 RayScene::sceneCentre(const Scene& scene) {
    const Bounds b = scene.bounds();
    return b.empty() ? glm::dvec3(0.0) : (glm::dvec3(b.min) + glm::dvec3(b.max)) * 0.5;
}

long long RayScene::buildCount() { return builds.load(); }

RayScene::~RayScene() = default;

glm::uvec3 RayScene::triangle(int instance, int triangle) const {
    const auto& idx = *instances_[instance].indices;
    const size_t k = static_cast<size_t>(triangle) * 3;
    return {idx[k], idx[k + 1], idx[k + 2]};
}

bool RayScene::cutOut(int instance, int tri, double u, double v) const {
    const InstanceGeometry& g = instances_[instance];
    const Material& m = materials_[g.material];
    if (m.alphaMode != AlphaMode::Mask) return false;
    const glm::uvec3 t = triangle(instance, tri);
    const double w = 1.0 - u - v;
    double alpha = m.baseColor.a * (w * g.colors[t.x].a + u * g.colors[t.y].a + v * g.colors[t.z].a);
    if (m.baseColorTexture >= 0) {
        const TextureMapping& map = m.mapping[Material::BaseColorSlot];
        const auto& uvs = map.texCoord == 1 ? g.uv1 : g.uv0;
        const glm::dvec2 uv = w * uvs[t.x] + u * uvs[t.y] + v * uvs[t.z];
        alpha *= sampleBilinear(maskImages_[m.baseColorTexture], map, transformUv(map, uv), true).a;
    }
    return alpha < m.alphaCutoff;
}

bool RayScene::blended(int instance) const {
    return materials_[instances_[instance].material].alphaMode == AlphaMode::Blend;
}

bool RayScene::backFacing(int instance, int tri, const glm::dvec3& dir) const {
    const InstanceGeometry& g = instances_[instance];
    if (materials_[g.material].doubleSided) return false;
    const glm::uvec3 t = triangle(instance, tri);
    glm::dvec3 ng = glm::cross(g.positions[t.y] - g.positions[t.x], g.positions[t.z] - g.positions[t.x]);
    if (g.mirrored) ng = -ng;
    return glm::dot(ng, dir) > 0.0;
}

RayHit RayScene::intersect(const glm::dvec3& org, const glm::dvec3& dir, double tNear, double tFar,
                           Visibility visibility) const {
    QueryContext ctx{};
    rtcInitIntersectContext(&ctx.embree);
    ctx.scene = this;
    ctx.visibility = visibility;
    ctx.blendedCastShadows = false;
    RTCRayHit rh{};
    rh.ray = makeRay(org, dir, tNear, tFar);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(embree_->scene, &ctx.embree, &rh);
    RayHit h;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
    h.hit = true;
    h.t = rh.ray.tfar;
    h.instance = static_cast<int>(rh.hit.geomID);
    h.triangle = static_cast<int>(rh.hit.primID);
    h.u = rh.hit.u;
    h.v = rh.hit.v;
    // Embree found the triangle in single precision; the point on it is
    // worked out again in double (Moller-Trumbore on the double vertices), so
    // a hit far from the origin is as exact as one near it.
    const InstanceGeometry& g = instances_[h.instance];
    const glm::uvec3 t = triangle(h.instance, h.triangle);
    const glm::dvec3 e1 = g.positions[t.y] - g.positions[t.x], e2 = g.positions[t.z] - g.positions[t.x];
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (det != 0.0 && std::isfinite(det)) {
        const glm::dvec3 s = org - g.positions[t.x];
        const glm::dvec3 q = glm::cross(s, e1);
        const double u = glm::dot(s, p) / det, v = glm::dot(dir, q) / det;
        // Keep Embree's answer where the double one leaves the triangle (an edge hit).
        if (u >= -1e-9 && v >= -1e-9 && u + v <= 1.0 + 1e-9) {
            h.u = std::clamp(u, 0.0, 1.0);
            h.v = std::clamp(v, 0.0, 1.0 - h.u);
            h.t = glm::dot(e2, q) / det;
        }
    }
    return h;
}

bool RayScene::occluded(const glm::dvec3& org, const glm::dvec3& dir, double tNear, double tFar,
                        bool blendedCastShadows) const {
    QueryContext ctx{};
    rtcInitIntersectContext(&ctx.embree);
    ctx.scene = this;
    ctx.visibility = Visibility::Shadow;
    ctx.blendedCastShadows = blendedCastShadows;
    RTCRay r = makeRay(org, dir, tNear, tFar);
    rtcOccluded1(embree_->scene, &ctx.embree, &r);
    return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace dw::reference
