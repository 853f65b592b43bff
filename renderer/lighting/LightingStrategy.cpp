#include "renderer/lighting/LightingStrategy.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cstddef>

#include "renderer/lighting/LightVolume.h"

namespace dw {

void LightShading::setup(gl::ShaderLibrary& shaders) {
    fullscreen_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag"});
    volume_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = {"VOLUME_ROW"}});
    fullscreenCounting_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP"}});
    volumeCounting_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP", "VOLUME_ROW"}});
    // Batches hold only lights without a shadow map (LightLists).
    volumeBatch_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = {"VOLUME_ROW", "UNSHADOWED"}});
    volumeBatchCounting_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP", "VOLUME_ROW", "UNSHADOWED"}});
    stencil_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/stencil.frag"});
    gl::MemoryOwner owner("light volume meshes");
    for (int k = 0; k <= kMaxSphereSubdivisions; ++k) sphere_[k].create(unitSphereVolume(k));
    cone_.create(unitConeVolume());
    batchVertexBuffer_ = gl::Buffer::create(sizeof(BatchVertex), nullptr, true, "light volume batch vertices");
    batchIndexBuffer_ = gl::Buffer::create(sizeof(std::uint32_t), nullptr, true, "light volume batch indices");
    batchVao_ = gl::VertexArray::create();
}

void LightShading::uploadVolumeBatch(const LightTable& table, const std::vector<std::uint32_t>& rows) const {
    batchVertices_.clear();
    batchIndices_.clear();
    batchIndexStart_.assign(1, 0u);
    batchVertexStart_.assign(1, 0u);
    for (const std::uint32_t row : rows) {
        const bool cone = table.entries[row].volume.shape == VolumeShape::Cone;
        const VolumeMesh& mesh = cone ? unitConeVolume() : unitSphereVolume(sphereSubdivisions_);
        const glm::mat4& m = table.rows[row].volume;  // unit mesh -> camera-relative world, as the GPU gets it
        const auto base = static_cast<std::uint32_t>(batchVertices_.size());
        for (const glm::vec3& p : mesh.positions) batchVertices_.push_back({glm::vec3(m * glm::vec4(p, 1.0f)), static_cast<float>(row)});
        for (const std::uint32_t i : mesh.indices) batchIndices_.push_back(base + i);
        batchIndexStart_.push_back(static_cast<std::uint32_t>(batchIndices_.size()));
        batchVertexStart_.push_back(static_cast<std::uint32_t>(batchVertices_.size()));
    }
    if (batchVertices_.empty()) return;
    gl::MemoryOwner owner("light volume meshes");
    batchVertexBuffer_.ensureSize(batchVertices_.size() * sizeof(BatchVertex), "light volume batch vertices");
    batchVertexBuffer_.update(0, batchVertices_.size() * sizeof(BatchVertex), batchVertices_.data());
    batchIndexBuffer_.ensureSize(batchIndices_.size() * sizeof(std::uint32_t), "light volume batch indices");
    batchIndexBuffer_.update(0, batchIndices_.size() * sizeof(std::uint32_t), batchIndices_.data());
    // (Re)attached every time: ensureSize may have replaced the buffers.
    batchVao_.setVertexBuffer(0, batchVertexBuffer_, 0, sizeof(BatchVertex));
    batchVao_.setIndexBuffer(batchIndexBuffer_);
    batchVao_.setAttribute(0, 0, 3, offsetof(BatchVertex, position));
    batchVao_.setAttribute(1, 0, 1, offsetof(BatchVertex, row));
}

void LightShading::drawVolumeBatch(const gl::Program& program, int first, int count) const {
    if (count <= 0) return;
    const std::uint32_t begin = batchIndexStart_[static_cast<std::size_t>(first)];
    const std::uint32_t end = batchIndexStart_[static_cast<std::size_t>(first + count)];
    program.set(0, -1);
    batchVao_.bind();
    // The lights of a batch are consecutive, so are their vertices: the range
    // spares the driver a scan of the indices for their bounds.
    glDrawRangeElements(GL_TRIANGLES, batchVertexStart_[static_cast<std::size_t>(first)],
                        batchVertexStart_[static_cast<std::size_t>(first + count)] - 1, static_cast<GLsizei>(end - begin),
                        GL_UNSIGNED_INT, reinterpret_cast<const void*>(static_cast<std::uintptr_t>(begin) * sizeof(std::uint32_t)));
}

std::pair<glm::vec3, glm::vec3> LightShading::localBox(VolumeShape shape) const {
    static const auto box = [](const VolumeMesh& m) {
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        return std::pair{lo, hi};
    };
    static const std::pair<glm::vec3, glm::vec3> spheres[] = {box(unitSphereVolume(0)), box(unitSphereVolume(1)),
                                                               box(unitSphereVolume(2)), box(unitSphereVolume(3))};
    static_assert(std::size(spheres) == kMaxSphereSubdivisions + 1);
    static const std::pair<glm::vec3, glm::vec3> cone = box(unitConeVolume());
    return shape == VolumeShape::Cone ? cone : spheres[sphereSubdivisions_];
}

StrategyCounts drawEachLightInView(LightingFrame& f, const std::function<void(const LightTableEntry&)>& draw) {
    StrategyCounts c;
    for (const LightTableEntry* e : f.lights) {
        if (!e->inFrustum) {
            ++c.culled;
            continue;
        }
        draw(*e);
        ++c.volumes;
    }
    return c;
}

}  // namespace dw
