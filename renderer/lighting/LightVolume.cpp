#include "renderer/lighting/LightVolume.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <map>

namespace dw {

double solveLightRadius(const Attenuation& att, double maxIntensity, double threshold) {
    if (!(maxIntensity > 0.0) || !(threshold > 0.0)) return 0.0;
    const double c = att.constant, l = att.linear, q = att.quadratic;
    const double k = maxIntensity / threshold;  // the denominator value at the radius
    if (c >= k) return 0.0;                     // never brighter than the threshold
    if (q <= 0.0 && l <= 0.0) return std::numeric_limits<double>::infinity();
    // Root of q d^2 + l d + (c - k) = 0 in the form without cancellation:
    // d = 2 (k - c) / (l + sqrt(l^2 + 4 q (k - c))).
    const double e = k - c;
    return 2.0 * e / (l + std::sqrt(l * l + 4.0 * q * e));
}

namespace {

glm::mat4 basisFromDirection(const glm::vec3& position, const glm::vec3& dir) {
    const glm::vec3 z = glm::normalize(dir);
    const glm::vec3 helper = std::fabs(z.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 x = glm::normalize(glm::cross(helper, z));
    const glm::vec3 y = glm::cross(z, x);
    glm::mat4 m(1.0f);
    m[0] = glm::vec4(x, 0.0f);
    m[1] = glm::vec4(y, 0.0f);
    m[2] = glm::vec4(z, 0.0f);
    m[3] = glm::vec4(position, 1.0f);
    return m;
}

}  // namespace

LightVolume computeLightVolume(const Light& light, double threshold) {
    LightVolume v;
    if (!light.enabled || light.type == LightType::Directional) {
        v.shape = light.type == LightType::Directional && light.enabled ? VolumeShape::FullScreen : VolumeShape::Culled;
        v.radius = std::numeric_limits<double>::infinity();
        return v;
    }
    const double imax = std::max({light.intensity.r, light.intensity.g, light.intensity.b});
    v.radius = solveLightRadius(light.attenuation, imax, threshold);
    if (v.radius <= 0.0) {
        v.shape = VolumeShape::Culled;
        return v;
    }
    if (!std::isfinite(v.radius) || v.radius > 1e7) {
        v.shape = VolumeShape::FullScreen;
        return v;
    }
    const auto r = static_cast<float>(v.radius);
    if (light.type == LightType::Spot) {
        const double t = std::tan(glm::radians(static_cast<double>(light.cutoffDegrees)));
        if (light.cutoffDegrees < 89.9f && t * t < 4.0) {
            v.shape = VolumeShape::Cone;
            const auto base = static_cast<float>(v.radius * t);
            v.transform = glm::scale(basisFromDirection(light.position, light.direction), glm::vec3(base, base, r));
            return v;
        }
    }
    v.shape = VolumeShape::Sphere;
    v.transform = glm::scale(glm::translate(glm::mat4(1.0f), light.position), glm::vec3(r));
    return v;
}

bool VolumeMesh::contains(const glm::mat4& transform, const glm::vec3& p, float epsilon) const {
    // Convex and wound counter-clockwise seen from outside: inside = behind every face.
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
        const glm::vec3 a(transform * glm::vec4(positions[indices[i]], 1.0f));
        const glm::vec3 b(transform * glm::vec4(positions[indices[i + 1]], 1.0f));
        const glm::vec3 c(transform * glm::vec4(positions[indices[i + 2]], 1.0f));
        const glm::vec3 n = glm::cross(b - a, c - a);
        const float len = glm::length(n);
        if (len < 1e-12f) continue;
        if (glm::dot(n / len, p - a) > epsilon) return false;
    }
    return true;
}

const VolumeMesh& unitSphereVolume(int subdivisions) {
    static const auto build = [](int levels) {
        VolumeMesh m;
        const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
        m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        for (auto& p : m.positions) p = glm::normalize(p);
        m.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                     3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
        for (int level = 0; level < levels; ++level) {
            std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
            auto midpoint = [&](uint32_t a, uint32_t b) {
                const auto key = std::minmax(a, b);
                auto it = mid.find(key);
                if (it != mid.end()) return it->second;
                m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
                const auto idx = static_cast<uint32_t>(m.positions.size() - 1);
                mid[key] = idx;
                return idx;
            };
            std::vector<uint32_t> next;
            for (size_t i = 0; i < m.indices.size(); i += 3) {
                const uint32_t a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
                const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
                next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
            }
            m.indices = std::move(next);
        }
        // Push the faces out so the smallest face distance (inradius) is 1.
        float inradius = 1.0f;
        for (size_t i = 0; i < m.indices.size(); i += 3) {
            const glm::vec3 a = m.positions[m.indices[i]], b = m.positions[m.indices[i + 1]], c = m.positions[m.indices[i + 2]];
            const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
            inradius = std::min(inradius, glm::dot(n, a));
        }
        for (auto& p : m.positions) p /= inradius * 0.9999f;
        return m;
    };
    static const VolumeMesh meshes[kMaxSphereSubdivisions + 1] = {build(0), build(1), build(2), build(3)};
    return meshes[std::clamp(subdivisions, 0, kMaxSphereSubdivisions)];
}

const VolumeMesh& unitConeVolume() {
    static const VolumeMesh mesh = [] {
        VolumeMesh m;
        const int n = 24;
        // The polygon's inradius is 1 when its circumradius is 1/cos(pi/n).
        const float R = 1.0f / std::cos(glm::pi<float>() / n) / 0.9999f;
        m.positions.push_back({0, 0, 0});  // apex
        m.positions.push_back({0, 0, 1});  // base centre
        for (int i = 0; i < n; ++i) {
            const float a = static_cast<float>(i) / n * glm::two_pi<float>();
            m.positions.push_back({R * std::cos(a), R * std::sin(a), 1.0f});
        }
        for (int i = 0; i < n; ++i) {
            const auto a = static_cast<uint32_t>(2 + i), b = static_cast<uint32_t>(2 + (i + 1) % n);
            m.indices.insert(m.indices.end(), {0u, b, a});  // side, outward
            m.indices.insert(m.indices.end(), {1u, a, b});  // base cap, facing +Z
        }
        return m;
    }();
    return mesh;
}

std::vector<int> lightsCovering(const std::vector<Light>& lights, const glm::vec3& p, double threshold, int sphereSubdivisions) {
    std::vector<int> out;
    for (size_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        if (!l.enabled || l.type == LightType::Directional) continue;
        const LightVolume v = computeLightVolume(l, threshold);
        const bool inside = v.shape == VolumeShape::FullScreen ||
                            (v.shape == VolumeShape::Sphere && unitSphereVolume(sphereSubdivisions).contains(v.transform, p)) ||
                            (v.shape == VolumeShape::Cone && unitConeVolume().contains(v.transform, p));
        if (inside) out.push_back(static_cast<int>(i));
    }
    return out;
}

}  // namespace dw
