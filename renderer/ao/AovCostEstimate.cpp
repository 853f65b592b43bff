#include "renderer/ao/AovCostEstimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "renderer/knobs/KnobRegistry.h"
#include "renderer/scene/Camera.h"
#include "renderer/scene/Mesh.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {

using Polygon = std::vector<glm::dvec2>;

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Convex hull (Andrew's monotone chain), counter-clockwise; `p` is sorted in place.
Polygon hull(std::array<glm::dvec2, 6>& p) {
    std::sort(p.begin(), p.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    Polygon h(12);
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
        h[k++] = p[i];
    }
    h.resize(k > 1 ? k - 1 : k);
    return h;
}

// Sutherland-Hodgman against one side of the NDC square: keeps s * x[axis] <= 1.
Polygon clipSide(const Polygon& in, int axis, double s) {
    Polygon out;
    out.reserve(in.size() + 2);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const glm::dvec2& a = in[i];
        const glm::dvec2& b = in[(i + 1) % in.size()];
        const double da = 1.0 - s * a[axis], db = 1.0 - s * b[axis];
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// Area of the polygon inside [-1, 1]^2, as a share of the square.
double screenShare(Polygon p) {
    for (int axis = 0; axis < 2 && !p.empty(); ++axis)
        for (double s : {1.0, -1.0}) p = clipSide(p, axis, s);
    double a = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec2& u = p[i];
        const glm::dvec2& v = p[(i + 1) % p.size()];
        a += u.x * v.y - v.x * u.y;
    }
    return std::abs(a) * 0.5 / 4.0;
}

}  // namespace

AovCostEstimate AovCostEstimate::compute(const Scene& scene, const glm::mat4& view, const glm::mat4& projection,
                                         float nearPlane, float radius) {
    AovCostEstimate e;
    e.radius = radius;
    const double delta = radius;
    const glm::dmat4 proj(projection);
    for (const MeshInstance& inst : scene.instances) {
        if (inst.mesh < 0 || static_cast<std::size_t>(inst.mesh) >= scene.meshes.size()) continue;
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(inst.mesh)];
        const Material* mat = mesh.material >= 0 && static_cast<std::size_t>(mesh.material) < scene.materials.size()
                                  ? &scene.materials[static_cast<std::size_t>(mesh.material)]
                                  : nullptr;
        if (mat && mat->alphaMode == AlphaMode::Blend) continue;
        const bool doubleSided = mat && mat->doubleSided;
        const glm::dmat4 modelView = glm::dmat4(view) * glm::dmat4(inst.transform);
        const bool mirrored = glm::determinant(glm::dmat3(modelView)) < 0.0;
        std::vector<glm::dvec3> viewPos(mesh.vertices.size());
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
            viewPos[i] = glm::dvec3(modelView * glm::dvec4(glm::dvec3(mesh.vertices[i].position), 1.0));
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
            if (i0 >= viewPos.size() || i1 >= viewPos.size() || i2 >= viewPos.size()) continue;
            const std::array<glm::dvec3, 3> v = {viewPos[i0], viewPos[i1], viewPos[i2]};
            const glm::dvec3 crossed = glm::cross(v[1] - v[0], v[2] - v[0]);
            const double len = glm::length(crossed);
            // Degenerate triangles extrude nothing (as in the geometry shader).
            if (!(len > 1e-12 * std::max(glm::dot(v[1] - v[0], v[1] - v[0]), glm::dot(v[2] - v[0], v[2] - v[0]))))
                continue;
            const glm::dvec3 middle = (v[0] + v[1] + v[2]) / 3.0;
            std::array<glm::dvec3, 3> edge;
            const glm::dvec3 n0 = (mirrored ? -crossed : crossed) / len;
            for (int i = 0; i < 3; ++i) {
                const glm::dvec3 m = glm::normalize(glm::cross(v[(i + 1) % 3] - v[i], n0));
                edge[i] = glm::dot(m, middle - v[i]) > 0.0 ? -m : m;
            }
            for (int side = 0; side < (doubleSided ? 2 : 1); ++side) {
                const glm::dvec3 n = side == 0 ? n0 : -n0;
                ++e.volumes;
                std::array<glm::dvec3, 6> corner;
                for (int i = 0; i < 3; ++i) {
                    const glm::dvec3 ep = edge[(i + 2) % 3], en = edge[i];
                    corner[i] = v[i] + delta * (ep + en) / std::max(1.0 + glm::dot(ep, en), 0.1);
                    corner[i + 3] = corner[i] + delta * n;
                }
                std::array<glm::dvec4, 6> clip;
                bool out[4] = {true, true, true, true};
                bool behind = true, reachesNear = false;
                for (int i = 0; i < 6; ++i) {
                    clip[i] = proj * glm::dvec4(corner[i], 1.0);
                    const glm::dvec4& c = clip[i];
                    out[0] = out[0] && c.x > c.w;
                    out[1] = out[1] && c.x < -c.w;
                    out[2] = out[2] && c.y > c.w;
                    out[3] = out[3] && c.y < -c.w;
                    behind = behind && corner[i].z >= 0.0;
                    reachesNear = reachesNear || -corner[i].z < nearPlane;
                }
                if (out[0] || out[1] || out[2] || out[3] || behind) {
                    ++e.culled;
                    continue;
                }
                if (reachesNear) {
                    ++e.nearCamera;
                    e.meanOverdraw += 1.0;
                    continue;
                }
                std::array<glm::dvec2, 6> ndc;
                for (int i = 0; i < 6; ++i) ndc[i] = glm::dvec2(clip[i]) / clip[i].w;
                e.meanOverdraw += screenShare(hull(ndc));
            }
        }
    }
    return e;
}

std::optional<AovCostEstimate> AovCostEstimate::forKnobs(const KnobRegistry& knobs, const Scene& scene,
                                                         const Camera& camera, int width, int height) {
    const auto enabled = knobs.find("ao.enabled"), method = knobs.find("ao.method"), radius = knobs.find("aov.radius");
    if (!enabled || !method || !radius || knobs.value(*enabled) == 0.0) return std::nullopt;
    const KnobSpec& m = knobs.spec(*method);
    if (m.choices.at(static_cast<std::size_t>(knobs.value(*method))) != "aov") return std::nullopt;
    double r = knobs.value(*radius);
    if (const auto unit = knobs.find("aov.radius_unit"))
        if (knobs.spec(*unit).choices.at(static_cast<std::size_t>(knobs.value(*unit))) != "world")
            r *= sceneLengthUnit(scene.bounds());
    const float aspect = height > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f;
    return compute(scene, camera.view(), camera.projection(aspect), camera.nearPlane, static_cast<float>(r));
}

std::pair<int, int> AovCostEstimate::aoSize(const KnobRegistry& knobs, int width, int height) {
    int shift = 0;
    if (const auto res = knobs.find("aov.resolution")) shift = static_cast<int>(knobs.value(*res));
    return {std::max(1, width >> shift), std::max(1, height >> shift)};
}

namespace {
std::string duration(double seconds) {
    char text[64];
    if (seconds < 10.0) std::snprintf(text, sizeof(text), "%.2g s", seconds);
    else if (seconds < 90.0) std::snprintf(text, sizeof(text), "%.0f s", seconds);
    else if (seconds < 90.0 * 60.0) std::snprintf(text, sizeof(text), "%.0f minutes", seconds / 60.0);
    else if (seconds < 48.0 * 3600.0) std::snprintf(text, sizeof(text), "%.*f hours", seconds < 36000.0 ? 1 : 0, seconds / 3600.0);
    else std::snprintf(text, sizeof(text), "%.0f days", seconds / 86400.0);
    return text;
}
}  // namespace

std::string AovCostEstimate::timeRange(double fragments) {
    std::string low = duration(fragments * kSecondsPerFragmentLow);
    const std::string high = duration(fragments * kSecondsPerFragmentHigh);
    // "10 to 60 minutes" when both are in the same unit.
    const auto lowUnit = low.find(' '), highUnit = high.find(' ');
    if (low.substr(lowUnit) == high.substr(highUnit)) low.resize(lowUnit);
    return "about " + low + " to " + high;
}

std::string AovCostEstimate::warning(const AovCostEstimate& e, const KnobRegistry& knobs, int width, int height) {
    const auto [aw, ah] = aoSize(knobs, width, height);
    if (!exceeds(e, aw, ah)) return {};
    std::string resolution = "full", unit = "world";
    if (const auto res = knobs.find("aov.resolution"))
        resolution = knobs.spec(*res).choices.at(static_cast<std::size_t>(knobs.value(*res)));
    if (const auto u = knobs.find("aov.radius_unit"))
        unit = knobs.spec(*u).choices.at(static_cast<std::size_t>(knobs.value(*u)));
    const double millions = e.fragments(aw, ah) / 1e6;
    char line[768];
    std::snprintf(line, sizeof(line),
                  "aov: about %.0f volume fragments per pixel expected, %.*f million at %dx%d (aov.resolution %s; "
                  "estimated from the scene's %zu volumes, %zu in view, %zu reaching the near plane, at aov.radius "
                  "%.4g world units), %s a frame on llvmpipe; over the limit of %.0f a pixel or %.3g "
                  "million a frame: lower aov.radius%s, or aov.resolution",
                  e.meanOverdraw, millions >= 10.0 ? 0 : 2, millions, aw, ah, resolution.c_str(), e.volumes,
                  e.volumes - e.culled, e.nearCamera, e.radius, timeRange(e.fragments(aw, ah)).c_str(),
                  kWarnOverdraw, kWarnFragments / 1e6,
                  unit == "world" ? " (aov.radius_unit=scene_fraction makes it relative to the scene's size)" : "");
    return line;
}

std::string AovCostEstimate::check(const KnobRegistry& knobs, const Scene& scene, const Camera& camera, int width,
                                   int height) {
    const auto e = forKnobs(knobs, scene, camera, width, height);
    return e ? warning(*e, knobs, width, height) : std::string{};
}

}  // namespace dw
