#include "renderer/scene/NormalGenerator.h"

#include <cmath>

#include "renderer/scene/Mesh.h"
#include "renderer/scene/UnitVector.h"

namespace dw {

namespace {

// In double: a triangle 1e-20 across has a cross product below the smallest
// float, one 1e30 across beyond the largest (UnitVector.h).
glm::dvec3 faceNormalTimesTwoArea(const Mesh& m, size_t t) {
    const glm::dvec3 p0 = m.vertices[m.indices[3 * t]].position;
    const glm::dvec3 p1 = m.vertices[m.indices[3 * t + 1]].position;
    const glm::dvec3 p2 = m.vertices[m.indices[3 * t + 2]].position;
    return glm::cross(p1 - p0, p2 - p0);
}

glm::vec3 unitOr(const glm::dvec3& v, const glm::vec3& fallback) { return unitVector(v, fallback); }

}  // namespace

void generateFlatNormals(Mesh& mesh) {
    const size_t triangles = mesh.indices.size() / 3;
    std::vector<Vertex> vertices;
    vertices.reserve(triangles * 3);
    for (size_t t = 0; t < triangles; ++t) {
        const glm::vec3 n = unitOr(faceNormalTimesTwoArea(mesh, t), glm::vec3(0, 1, 0));
        for (int c = 0; c < 3; ++c) {
            Vertex v = mesh.vertices[mesh.indices[3 * t + static_cast<size_t>(c)]];
            v.normal = n;
            vertices.push_back(v);
        }
    }
    mesh.vertices = std::move(vertices);
    mesh.indices.resize(triangles * 3);
    for (size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
}

std::size_t orientTrianglesToNormals(Mesh& mesh) {
    const size_t triangles = mesh.indices.size() / 3;
    std::vector<size_t> against;
    size_t counted = 0;
    for (size_t t = 0; t < triangles; ++t) {
        const glm::dvec3 face = faceNormalTimesTwoArea(mesh, t);
        if (!(glm::dot(face, face) > 0.0)) continue;
        ++counted;
        glm::dvec3 vertexNormals(0.0);
        for (int c = 0; c < 3; ++c) vertexNormals += glm::dvec3(mesh.vertices[mesh.indices[3 * t + static_cast<size_t>(c)]].normal);
        if (glm::dot(face, vertexNormals) < 0.0) against.push_back(t);
    }
    if (against.empty() || 2 * against.size() >= counted) return 0;
    for (size_t t : against) std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
    return against.size();
}

std::size_t splitCornersFacingAway(Mesh& mesh) {
    std::size_t split = 0;
    const size_t triangles = mesh.indices.size() / 3;
    for (size_t t = 0; t < triangles; ++t) {
        const glm::dvec3 face = faceNormalTimesTwoArea(mesh, t);
        if (!(glm::dot(face, face) > 0.0)) continue;
        for (int c = 0; c < 3; ++c) {
            std::uint32_t& index = mesh.indices[3 * t + static_cast<size_t>(c)];
            if (glm::dot(face, glm::dvec3(mesh.vertices[index].normal)) >= 0.0) continue;
            Vertex v = mesh.vertices[index];
            v.normal = unitOr(face, v.normal);
            index = static_cast<std::uint32_t>(mesh.vertices.size());
            mesh.vertices.push_back(v);
            ++split;
        }
    }
    return split;
}

std::size_t repairNormals(Mesh& mesh, const std::vector<bool>& repair) {
    std::vector<glm::dvec3> sum(mesh.vertices.size(), glm::dvec3(0.0));
    for (size_t t = 0; t < mesh.indices.size() / 3; ++t) {
        const glm::dvec3 fn = faceNormalTimesTwoArea(mesh, t);
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = mesh.indices[3 * t + static_cast<size_t>(c)];
            if (repair[v]) sum[v] += fn;
        }
    }
    std::size_t count = 0;
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (repair[v]) {
            mesh.vertices[v].normal = unitOr(sum[v], glm::vec3(0, 1, 0));
            ++count;
        }
    return count;
}

}  // namespace dw
