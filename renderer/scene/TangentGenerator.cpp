#include "renderer/scene/TangentGenerator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <vector>

#include "renderer/scene/Mesh.h"
#include "renderer/scene/UnitVector.h"

namespace dw {

namespace {

// A corner's identity for averaging: the exact bits of position, normal and
// uv, plus the orientation of its triangle in UV space.
using CornerKey = std::array<std::uint32_t, 9>;

CornerKey keyOf(const Vertex& v, int orientation) {
    CornerKey k{};
    const float f[8] = {v.position.x, v.position.y, v.position.z, v.normal.x, v.normal.y, v.normal.z, v.uv.x, v.uv.y};
    for (int i = 0; i < 8; ++i) {
        // +0 and -0 are the same value.
        const float x = f[i] == 0.0f ? 0.0f : f[i];
        std::memcpy(&k[static_cast<size_t>(i)], &x, 4);
    }
    k[8] = orientation > 0 ? 1u : 0u;
    return k;
}

// In double, as the face tangents: edges 1e-20 long have squares below a float.
float cornerAngle(const glm::vec3& at, const glm::vec3& a, const glm::vec3& b) {
    const glm::dvec3 e1 = glm::dvec3(a) - glm::dvec3(at), e2 = glm::dvec3(b) - glm::dvec3(at);
    const double l1 = glm::length(e1), l2 = glm::length(e2);
    if (!(l1 > 0.0) || !(l2 > 0.0)) return 0.0f;
    return static_cast<float>(std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0, 1.0)));
}

glm::vec3 anyPerpendicular(const glm::vec3& n) {
    const glm::vec3 t = std::fabs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0)) : glm::cross(n, glm::vec3(0, 1, 0));
    const float l = glm::length(t);
    return l > 0.0f ? t / l : glm::vec3(1, 0, 0);
}

}  // namespace

void generateTangents(Mesh& mesh, UvConvention convention) {
    const float handedness = convention == UvConvention::GltfVDown ? -1.0f : 1.0f;
    const size_t triangles = mesh.indices.size() / 3;
    // Per triangle: dP/du and the orientation (sign of the signed UV area; 0 when degenerate).
    std::vector<glm::vec3> faceTangent(triangles, glm::vec3(0.0f));
    std::vector<int> orientation(triangles, 0);
    for (size_t t = 0; t < triangles; ++t) {
        const Vertex& v0 = mesh.vertices[mesh.indices[3 * t]];
        const Vertex& v1 = mesh.vertices[mesh.indices[3 * t + 1]];
        const Vertex& v2 = mesh.vertices[mesh.indices[3 * t + 2]];
        // In double, and degenerate relative to the UV edges' lengths, so a
        // box 1e-12 across (UVs 1e-12 apart, UV area 1e-24) is shaded as one
        // 1 across; only the direction is kept.
        const glm::dvec3 e1 = glm::dvec3(v1.position) - glm::dvec3(v0.position);
        const glm::dvec3 e2 = glm::dvec3(v2.position) - glm::dvec3(v0.position);
        const glm::dvec2 d1 = glm::dvec2(v1.uv) - glm::dvec2(v0.uv), d2 = glm::dvec2(v2.uv) - glm::dvec2(v0.uv);
        const double area = d1.x * d2.y - d2.x * d1.y;
        if (!std::isfinite(area) || !(std::fabs(area) > 1e-12 * glm::length(d1) * glm::length(d2))) continue;
        orientation[t] = area > 0.0 ? 1 : -1;
        faceTangent[t] = unitVector((e1 * d2.y - e2 * d1.y) / area, glm::vec3(0.0f));
    }

    // Group the corners; degenerate-UV triangles join a group of either
    // orientation that already exists at their corner (second pass).
    std::map<CornerKey, std::uint32_t> groupOf;
    std::vector<glm::vec3> groupTangent;
    std::vector<int> groupSign;
    std::vector<std::uint32_t> cornerGroup(mesh.indices.size(), 0);
    auto groupFor = [&](const Vertex& v, int orient) {
        auto [it, inserted] = groupOf.try_emplace(keyOf(v, orient), static_cast<std::uint32_t>(groupTangent.size()));
        if (inserted) {
            groupTangent.emplace_back(0.0f);
            groupSign.push_back(orient);
        }
        return it->second;
    };
    for (int pass = 0; pass < 2; ++pass) {
        for (size_t t = 0; t < triangles; ++t) {
            if ((orientation[t] == 0) != (pass == 1)) continue;
            for (int c = 0; c < 3; ++c) {
                const size_t corner = 3 * t + static_cast<size_t>(c);
                const Vertex& v = mesh.vertices[mesh.indices[corner]];
                if (pass == 0) {
                    const std::uint32_t g = groupFor(v, orientation[t]);
                    cornerGroup[corner] = g;
                    const glm::vec3 p1 = mesh.vertices[mesh.indices[3 * t + (c + 1) % 3]].position;
                    const glm::vec3 p2 = mesh.vertices[mesh.indices[3 * t + (c + 2) % 3]].position;
                    const glm::vec3 n = v.normal;
                    glm::vec3 projected = faceTangent[t] - n * glm::dot(n, faceTangent[t]);
                    const float len = glm::length(projected);
                    if (len > 1e-20f && std::isfinite(len))
                        groupTangent[g] += (projected / len) * cornerAngle(v.position, p1, p2);
                } else {
                    auto it = groupOf.find(keyOf(v, 1));
                    if (it == groupOf.end()) it = groupOf.find(keyOf(v, -1));
                    cornerGroup[corner] = it != groupOf.end() ? it->second : groupFor(v, 1);
                }
            }
        }
    }

    // One output vertex per (input vertex, group).
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> outIndex;
    std::vector<Vertex> vertices;
    vertices.reserve(mesh.vertices.size());
    std::vector<std::uint32_t> indices(mesh.indices.size());
    for (size_t corner = 0; corner < triangles * 3; ++corner) {
        const std::uint32_t src = mesh.indices[corner], g = cornerGroup[corner];
        auto [it, inserted] = outIndex.try_emplace({src, g}, static_cast<std::uint32_t>(vertices.size()));
        if (inserted) {
            Vertex v = mesh.vertices[src];
            const glm::vec3 sum = groupTangent[g];
            const float len = glm::length(sum);
            const glm::vec3 t = len > 1e-20f && std::isfinite(len) ? sum / len : anyPerpendicular(v.normal);
            v.tangent = glm::vec4(t, groupSign[g] < 0 ? -handedness : handedness);
            vertices.push_back(v);
        }
        indices[corner] = it->second;
    }
    mesh.vertices = std::move(vertices);
    mesh.indices = std::move(indices);
}

}  // namespace dw
