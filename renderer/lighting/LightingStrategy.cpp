#include "renderer/lighting/LightingStrategy.h"

#include <algorithm>

#include "renderer/lighting/LightVolume.h"

namespace dw {

void LightShading::setup(gl::ShaderLibrary& shaders) {
    fullscreen_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag"});
    volume_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = {"VOLUME_ROW"}});
    fullscreenCounting_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP"}});
    volumeCounting_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP", "VOLUME_ROW"}});
    stencil_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/stencil.frag"});
    for (int k = 0; k <= kMaxSphereSubdivisions; ++k) sphere_[k].create(unitSphereVolume(k));
    cone_.create(unitConeVolume());
    volumeRows_ = gl::Buffer::create(sizeof(std::uint32_t), nullptr, true, "light volume rows");
}

void LightShading::uploadVolumeRows(const std::vector<std::uint32_t>& rows) const {
    volumeRows_.ensureSize(std::max<std::size_t>(rows.size(), 1) * sizeof(std::uint32_t), "light volume rows");
    if (!rows.empty()) volumeRows_.update(0, rows.size() * sizeof(std::uint32_t), rows.data());
    volumeRows_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::kVolumeRowsSsbo);
}

void LightShading::drawVolumes(const gl::Program& program, VolumeShape shape, int first, int count) const {
    if (count <= 0) return;
    program.set(0, -1);
    program.set(1, first);
    (shape == VolumeShape::Cone ? cone_ : sphere_[sphereSubdivisions_]).drawInstanced(count);
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

LightingStrategyCatalog& LightingStrategyCatalog::extra() {
    static LightingStrategyCatalog catalog;
    return catalog;
}

}  // namespace dw
