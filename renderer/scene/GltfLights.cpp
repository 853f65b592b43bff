#include "renderer/scene/GltfLights.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "renderer/Error.h"
#include "renderer/scene/CameraCheck.h"
#include "renderer/scene/GltfModelCheck.h"

namespace dw {

void GltfLightImporter::fail(const std::string& what) const { throw FileError(path_, what); }

// The unit vector along world * axis; none when the transform has no
// extent along it (zero scale) or is not finite. Scaled by the largest
// component first, so tiny or huge scales neither underflow nor overflow.
std::optional<glm::vec3> GltfLightImporter::unitAxis(const glm::mat4& world, const glm::vec4& axis) {
    const glm::vec3 v(world * axis);
    const float m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(m > 0.0f) || !std::isfinite(m)) return std::nullopt;
    return glm::normalize(v / m);
}

void GltfLightImporter::importNodeLight(const tinygltf::Node& node, const glm::mat4& world, GltfImport& result) {
    auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end() || !it->second.Has("light")) return;
    const int li = it->second.Get("light").GetNumberAsInt();
    checkGltfIndex(li, model_.lights, path_, "node KHR_lights_punctual.light", false);
    const auto& l = model_.lights[li];
    Light out;
    out.name = l.name.empty() ? "light" + std::to_string(li) : l.name;
    const glm::vec3 color = l.color.size() >= 3 ? glm::vec3(l.color[0], l.color[1], l.color[2]) : glm::vec3(1.0f);
    out.intensity = color * static_cast<float>(l.intensity);
    out.position = glm::vec3(world[3]);
    const auto along = unitAxis(world, glm::vec4(0, 0, -1, 0));
    if (!along && l.type != "point")
        fail("light " + std::to_string(li) + " ('" + out.name + "'): its node's transform has zero scale, so the light has no direction");
    if (!std::isfinite(out.position.x + out.position.y + out.position.z))
        fail("light " + std::to_string(li) + " ('" + out.name + "'): its node's transform puts it beyond 32-bit float range");
    out.direction = along.value_or(glm::vec3(0, 0, -1));
    // glTF punctual lights fall off as 1/d^2 (candela units are kept as they are).
    out.attenuation = {0.0f, 0.0f, 1.0f};
    if (l.type == "directional") {
        out.type = LightType::Directional;
    } else if (l.type == "spot") {
        out.type = LightType::Spot;
        // GltfCheck allows pi/2 rounded to a float; the cone itself stops at pi/2.
        const double outer = l.spot.outerConeAngle > 0 ? std::min(l.spot.outerConeAngle, glm::half_pi<double>())
                                                       : glm::pi<double>() / 4.0;
        const double inner = std::clamp(l.spot.innerConeAngle, 0.0, outer);
        // The extension's own falloff: full inside the inner cone, 0 at the outer one.
        out.falloff = SpotFalloff::InnerOuterCone;
        out.cutoffDegrees = static_cast<float>(glm::degrees(outer));
        out.innerConeDegrees = std::min(static_cast<float>(glm::degrees(inner)), out.cutoffDegrees);
        out.exponent = 0.0f;
    } else {
        out.type = LightType::Point;
    }
    scene_.lights.push_back(out);
    ++result.lightCount;
}

void GltfLightImporter::importCamera(const tinygltf::Camera& cam, const glm::mat4& world, GltfImport& result) {
    if (cam.type != "perspective") return;
    Camera c;
    const std::string name = "camera[" + std::to_string(&cam - model_.cameras.data()) + "]";
    const auto forward = unitAxis(world, glm::vec4(0, 0, -1, 0)), up = unitAxis(world, glm::vec4(0, 1, 0, 0));
    if (!forward || !up)
        fail(name + ": its node's transform has zero scale (or overflows), so the camera has no view direction");
    c.position = glm::vec3(world[3]);
    c.target = c.position + *forward;
    c.up = *up;
    c.fovYDegrees = static_cast<float>(glm::degrees(cam.perspective.yfov));
    c.nearPlane = static_cast<float>(cam.perspective.znear > 0 ? cam.perspective.znear : 0.05);
    c.farPlane = static_cast<float>(cam.perspective.zfar > c.nearPlane ? cam.perspective.zfar
                                                                 : std::max(1000.0, c.nearPlane * 1e4));
    if (const auto problem = findCameraProblem(c, 0.0f)) fail(name + " (as placed by its node): " + problem->field + " " + problem->what);
    scene_.camera = c;
    result.hasCamera = true;
}

}  // namespace dw
