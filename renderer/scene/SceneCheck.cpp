#include "renderer/scene/SceneCheck.h"

#include <algorithm>
#include <cmath>

#include "renderer/Error.h"
#include "renderer/io/FloatCheck.h"
#include "renderer/scene/CameraCheck.h"

namespace dw {

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void warnClampedEmission(Scene& scene) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        const float peak = std::max({m.emissive.x, m.emissive.y, m.emissive.z});
        if (!(peak > kMaxEmission)) continue;
        const std::string name = m.name.empty() ? "materials[" + std::to_string(i) + "]" : m.name;
        scene.warnings.push_back(scene.source + ": material '" + name + "': emissive " + shortNumber(peak) +
                                 " is beyond 65000, the largest emission the G-buffer holds (R11G11B10F); clamped to "
                                 "65000 on opaque and blended surfaces and in the CPU reference");
    }
}

void checkSceneValues(const Scene& scene) {
    auto fail = [&](const std::string& what) { throw FileError(scene.source, what); };
    const Bounds b = scene.bounds();
    const float extent = b.empty() ? 0.0f : 2.0f * b.radius();
    if (!b.empty() && (!finite(b.min) || !finite(b.max) || !std::isfinite(extent)))
        fail("the scene's extent (" + shortNumber(b.min.x) + " .. " + shortNumber(b.max.x) + " in x, " +
             shortNumber(b.min.y) + " .. " + shortNumber(b.max.y) + " in y, " + shortNumber(b.min.z) + " .. " +
             shortNumber(b.max.z) + " in z) does not fit 32-bit floats");
    // Vertices: positions and texture coordinates the files gave (or a uv-scale
    // multiplied), normals and tangents derived from them (cross products overflow).
    // Attribute by attribute, so that the message names the given one (a
    // texture coordinate) before the one derived from it (a tangent).
    for (const Mesh& mesh : scene.meshes)
        for (int attribute = 0; attribute < 4; ++attribute)
            for (size_t v = 0; v < mesh.vertices.size(); ++v) {
                const Vertex& x = mesh.vertices[v];
                const bool ok = attribute == 0   ? finite(x.position)
                                : attribute == 1 ? finite(x.normal)
                                : attribute == 2 ? std::isfinite(x.uv.x) && std::isfinite(x.uv.y)
                                                 : finite(glm::vec3(x.tangent)) && std::isfinite(x.tangent.w);
                if (!ok) {
                    static const char* names[] = {"position", "normal", "texture coordinate", "tangent"};
                    fail("mesh '" + mesh.name + "': vertex " + std::to_string(v) + " has a " + names[attribute] +
                         " that does not fit 32-bit floats");
                }
            }
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const glm::mat4& m = scene.instances[i].transform;
        for (int c = 0; c < 4; ++c)
            if (!finite(glm::vec3(m[c])) || !std::isfinite(m[c][3]))
                fail("mesh '" + scene.meshes[scene.instances[i].mesh].name + "' (instance " + std::to_string(i) +
                     "): its transform does not fit 32-bit floats");
    }
    // Headroom for sums and squares: the L-buffer adds every light's radiance
    // (and bloom its levels) in 32-bit floats, and attenuation squares
    // distances. So light intensities, a light's peak over a constant-only
    // attenuation, and the ambient and background terms stay at or below
    // 1e30, and point and spot lights within 1e18 of the origin (d^2 <= 1e36).
    constexpr float kMaxRadiance = 1e30f, kMaxCoordinate = 1e18f;
    auto peak = [](const glm::vec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); };
    for (const Light& l : scene.lights) {
        if (!finite(l.position)) fail("light '" + l.name + "': its position does not fit 32-bit floats");
        if (!finite(l.direction)) fail("light '" + l.name + "': its direction is not finite");
        if (!finite(l.intensity)) fail("light '" + l.name + "': its intensity does not fit 32-bit floats");
        if (peak(l.intensity) > kMaxRadiance)
            fail("light '" + l.name + "': intensity " + shortNumber(peak(l.intensity)) +
                 " is beyond 1e30 (lights are summed in 32-bit floats)");
        if (l.type == LightType::Directional) continue;
        if (peak(l.position) > kMaxCoordinate)
            fail("light '" + l.name + "': position " + shortNumber(peak(l.position)) +
                 " is beyond 1e18 from the origin (attenuation squares distances in 32-bit floats)");
        const Attenuation& a = l.attenuation;
        const double unattenuated = double(peak(l.intensity)) / double(a.constant);  // in double: it may pass 3.4e38
        if (a.linear == 0.0f && a.quadratic == 0.0f && a.constant > 0.0f && unattenuated > kMaxRadiance)
            fail("light '" + l.name + "': intensity / attenuation.constant = " + shortNumber(unattenuated) +
                 " is beyond 1e30 (lights are summed in 32-bit floats)");
    }
    if (peak(scene.ambient) > kMaxRadiance) fail("ambient: " + shortNumber(peak(scene.ambient)) + " is beyond 1e30");
    if (peak(scene.background) > kMaxRadiance)
        fail("background: " + shortNumber(peak(scene.background)) + " is beyond 1e30");
    if (const auto problem = findCameraProblem(scene.camera, extent))
        fail("camera." + problem->field + ": " + problem->what + " (the scene is " + shortNumber(extent) + " across)");
}

}  // namespace dw
