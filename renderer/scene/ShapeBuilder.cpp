#include "renderer/scene/ShapeBuilder.h"

#include <glm/gtc/constants.hpp>

#include "renderer/scene/TangentGenerator.h"
#include "renderer/scene/UnitVector.h"

namespace dw::shapes {

namespace {

void addQuad(Mesh& m, const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v,
             const glm::vec2& uvSize) {
    // In double: any size a float holds gives a unit normal (UnitVector.h).
    const glm::vec3 n = unitVector(glm::cross(glm::dvec3(u), glm::dvec3(v)), glm::vec3(0, 1, 0));
    const glm::vec3 t = unitVector(glm::dvec3(u), glm::vec3(1, 0, 0));
    const auto base = static_cast<uint32_t>(m.vertices.size());
    const glm::vec3 corners[4] = {origin, origin + u, origin + u + v, origin + v};
    const glm::vec2 uvs[4] = {{0, 0}, {uvSize.x, 0}, {uvSize.x, uvSize.y}, {0, uvSize.y}};
    for (int i = 0; i < 4; ++i) m.vertices.push_back({corners[i], n, glm::vec4(t, 1.0f), uvs[i]});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

Mesh finish(Mesh m, const char* name) {
    m.name = name;
    generateTangents(m);
    m.computeBounds();
    return m;
}

}  // namespace

Mesh box(const glm::vec3& size, float uvScale) {
    Mesh m;
    const glm::vec3 h = size * 0.5f;
    const glm::vec3 X(size.x, 0, 0), Y(0, size.y, 0), Z(0, 0, size.z);
    // Each face as origin + u + v with u x v pointing outward.
    addQuad(m, {-h.x, -h.y, h.z}, X, Y, glm::vec2(size.x, size.y) * uvScale);   // +Z
    addQuad(m, {h.x, -h.y, -h.z}, -X, Y, glm::vec2(size.x, size.y) * uvScale);  // -Z
    addQuad(m, {h.x, -h.y, h.z}, -Z, Y, glm::vec2(size.z, size.y) * uvScale);   // +X
    addQuad(m, {-h.x, -h.y, -h.z}, Z, Y, glm::vec2(size.z, size.y) * uvScale);  // -X
    addQuad(m, {-h.x, h.y, h.z}, X, -Z, glm::vec2(size.x, size.z) * uvScale);   // +Y
    addQuad(m, {-h.x, -h.y, -h.z}, X, Z, glm::vec2(size.x, size.z) * uvScale);  // -Y
    return finish(std::move(m), "box");
}

Mesh plane(float sizeX, float sizeZ, float uvScale) {
    Mesh m;
    addQuad(m, {-sizeX * 0.5f, 0.0f, sizeZ * 0.5f}, {sizeX, 0, 0}, {0, 0, -sizeZ},
            glm::vec2(sizeX, sizeZ) * uvScale);
    return finish(std::move(m), "plane");
}

Mesh sphere(float radius, int slices, int stacks) {
    Mesh m;
    const float pi = glm::pi<float>();
    for (int j = 0; j <= stacks; ++j) {
        const float v = static_cast<float>(j) / stacks;
        const float theta = v * pi;
        for (int i = 0; i <= slices; ++i) {
            const float u = static_cast<float>(i) / slices;
            const float phi = u * 2.0f * pi;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            m.vertices.push_back({n * radius, n, glm::vec4(1, 0, 0, 1), {u * 2.0f, 1.0f - v}});
        }
    }
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const auto a = static_cast<uint32_t>(j * (slices + 1) + i);
            const auto b = a + static_cast<uint32_t>(slices + 1);
            for (uint32_t idx : {a, b, a + 1, a + 1, b, b + 1}) m.indices.push_back(idx);
        }
    return finish(std::move(m), "sphere");
}

Mesh cylinder(float radius, float height, int segments) {
    Mesh m;
    const float twoPi = 2.0f * glm::pi<float>();
    const float circumference = twoPi * radius;
    for (int i = 0; i <= segments; ++i) {
        const float u = static_cast<float>(i) / segments;
        const glm::vec3 n(std::cos(u * twoPi), 0.0f, -std::sin(u * twoPi));
        m.vertices.push_back({n * radius, n, {}, {u * circumference, 0.0f}});
        m.vertices.push_back({n * radius + glm::vec3(0, height, 0), n, {}, {u * circumference, height}});
    }
    for (int i = 0; i < segments; ++i) {
        const auto a = static_cast<uint32_t>(2 * i);
        for (uint32_t idx : {a, a + 2, a + 1, a + 1, a + 2, a + 3}) m.indices.push_back(idx);
    }
    for (int cap = 0; cap < 2; ++cap) {
        const float y = cap ? height : 0.0f;
        const glm::vec3 n(0.0f, cap ? 1.0f : -1.0f, 0.0f);
        const auto center = static_cast<uint32_t>(m.vertices.size());
        m.vertices.push_back({{0, y, 0}, n, {}, {0.5f, 0.5f}});
        for (int i = 0; i <= segments; ++i) {
            const float a = static_cast<float>(i) / segments * twoPi;
            const glm::vec3 p(std::cos(a) * radius, y, -std::sin(a) * radius);
            m.vertices.push_back({p, n, {}, {0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a)}});
        }
        for (int i = 0; i < segments; ++i) {
            const auto a = center + 1 + static_cast<uint32_t>(i);
            if (cap)
                for (uint32_t idx : {center, a, a + 1}) m.indices.push_back(idx);
            else
                for (uint32_t idx : {center, a + 1, a}) m.indices.push_back(idx);
        }
    }
    return finish(std::move(m), "cylinder");
}

Mesh cone(float radius, float height, int segments) {
    Mesh m;
    const float twoPi = 2.0f * glm::pi<float>();
    for (int i = 0; i <= segments; ++i) {
        const float u = static_cast<float>(i) / segments;
        const float a = u * twoPi;
        const glm::vec3 radial(std::cos(a), 0.0f, -std::sin(a));
        // radial + (0, radius / height, 0), scaled by height: radius / height
        // is infinite for a cone 1e-40 high.
        const glm::vec3 n = unitVector(glm::dvec3(radial) * double(height) + glm::dvec3(0, radius, 0), glm::vec3(0, 1, 0));
        m.vertices.push_back({radial * radius, n, {}, {u, 0.0f}});
        m.vertices.push_back({{0, height, 0}, n, {}, {u, 1.0f}});
    }
    for (int i = 0; i < segments; ++i) {
        const auto a = static_cast<uint32_t>(2 * i);
        for (uint32_t idx : {a, a + 2, a + 1}) m.indices.push_back(idx);
    }
    const auto center = static_cast<uint32_t>(m.vertices.size());
    m.vertices.push_back({{0, 0, 0}, {0, -1, 0}, {}, {0.5f, 0.5f}});
    for (int i = 0; i <= segments; ++i) {
        const float a = static_cast<float>(i) / segments * twoPi;
        m.vertices.push_back({{std::cos(a) * radius, 0, -std::sin(a) * radius}, {0, -1, 0}, {},
                              {0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a)}});
    }
    for (int i = 0; i < segments; ++i) {
        const auto a = center + 1 + static_cast<uint32_t>(i);
        for (uint32_t idx : {center, a + 1, a}) m.indices.push_back(idx);
    }
    return finish(std::move(m), "cone");
}

}  // namespace dw::shapes
