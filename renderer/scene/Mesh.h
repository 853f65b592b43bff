#pragma once
// One drawable primitive: indexed triangles with a single material.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace dw {

struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w = bitangent sign
    glm::vec2 uv{0.0f};                          // glTF TEXCOORD_0
    glm::vec4 color{1.0f};                       // glTF COLOR_0 (linear), multiplies the base colour
    glm::vec2 uv1{0.0f};                         // glTF TEXCOORD_1
};
static_assert(sizeof(Vertex) == 72, "Vertex layout is mirrored by the geometry VAO");

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    bool empty() const { return min.x > max.x; }
    void add(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void add(const Bounds& b) {
        if (!b.empty()) {
            add(b.min);
            add(b.max);
        }
    }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    // In double: the squares of a box 1e30 across overflow a float, of one 1e-25 across underflow it.
    float radius() const { return empty() ? 0.0f : static_cast<float>(glm::length(glm::dvec3(max) - glm::dvec3(min)) * 0.5); }
    Bounds transformed(const glm::mat4& m) const;
};

// The scene's length unit for settings given as a fraction of the scene's
// size (ssao.radius_unit = scene_fraction): 10^round(log10(R / 10)) for the
// bounding radius R, 1 for an empty or non-finite one. Shared by the SSAO
// pass and the CPU reference so both take the same radius.
double sceneLengthUnit(const Bounds& bounds);

struct Mesh {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    int material = 0;
    Bounds bounds;
    void computeBounds();
};

}  // namespace dw
