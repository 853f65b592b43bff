#include "renderer/scene/TangentGenerator.h"

#include <cmath>
#include <vector>

#include "renderer/scene/Mesh.h"

namespace dw {

void generateTangents(Mesh& mesh) {
    const size_t n = mesh.vertices.size();
    std::vector<glm::vec3> tan(n, glm::vec3(0.0f)), bit(n, glm::vec3(0.0f));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const uint32_t i0 = mesh.indices[i], i1 = mesh.indices[i + 1], i2 = mesh.indices[i + 2];
        const Vertex &v0 = mesh.vertices[i0], &v1 = mesh.vertices[i1], &v2 = mesh.vertices[i2];
        const glm::vec3 e1 = v1.position - v0.position, e2 = v2.position - v0.position;
        const glm::vec2 d1 = v1.uv - v0.uv, d2 = v2.uv - v0.uv;
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (std::fabs(det) < 1e-12f) continue;
        const float r = 1.0f / det;
        const glm::vec3 t = (e1 * d2.y - e2 * d1.y) * r;
        const glm::vec3 b = (e2 * d1.x - e1 * d2.x) * r;
        for (uint32_t idx : {i0, i1, i2}) {
            tan[idx] += t;
            bit[idx] += b;
        }
    }
    for (size_t i = 0; i < n; ++i) {
        Vertex& v = mesh.vertices[i];
        const glm::vec3 nrm = v.normal;
        glm::vec3 t = tan[i] - nrm * glm::dot(nrm, tan[i]);
        if (glm::dot(t, t) < 1e-20f) {
            // No usable UV gradient: any vector perpendicular to the normal.
            t = std::fabs(nrm.x) < 0.9f ? glm::cross(nrm, glm::vec3(1, 0, 0)) : glm::cross(nrm, glm::vec3(0, 1, 0));
        }
        t = glm::normalize(t);
        const float w = glm::dot(glm::cross(nrm, t), bit[i]) < 0.0f ? -1.0f : 1.0f;
        v.tangent = glm::vec4(t, w);
    }
}

void generateNormals(Mesh& mesh) {
    std::vector<glm::vec3> acc(mesh.vertices.size(), glm::vec3(0.0f));
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const uint32_t i0 = mesh.indices[i], i1 = mesh.indices[i + 1], i2 = mesh.indices[i + 2];
        const glm::vec3 fn = glm::cross(mesh.vertices[i1].position - mesh.vertices[i0].position,
                                        mesh.vertices[i2].position - mesh.vertices[i0].position);
        acc[i0] += fn;
        acc[i1] += fn;
        acc[i2] += fn;
    }
    for (size_t i = 0; i < acc.size(); ++i) {
        const float len = glm::length(acc[i]);
        mesh.vertices[i].normal = len > 0.0f ? acc[i] / len : glm::vec3(0, 1, 0);
    }
}

}  // namespace dw
