#pragma once
// CPU ground truth in double precision for the shading equation of
// shaders/common/lighting.glsl (Blinn-Phong, attenuation, spot factor) and the
// G-buffer encodings of shaders/common/gbuffer.glsl. Tests compare the GPU
// against these; the accuracy lab measures approximations against them.
#include <glm/glm.hpp>

#include "renderer/scene/Light.h"

namespace dw::reference {

enum class AttenuationModel { Classic, Windowed };

struct SurfacePoint {
    glm::dvec3 position;  // view space
    glm::dvec3 normal;    // view space, unit
    glm::dvec3 diffuse;
    glm::dvec3 specular;
    double exponent = 1.0;
};

// One light's reflected radiance towards the eye (at the view-space origin).
// `lightPosition`/`lightDirection` are in view space; `radius` <= 0 means unbounded.
glm::dvec3 shadeLight(const Light& light, const glm::dvec3& lightPosition, const glm::dvec3& lightDirection,
                      double radius, const SurfacePoint& s, AttenuationModel model, double windowExponent);
double attenuation(const Attenuation& a, double d, double radius, AttenuationModel model, double windowExponent);
// A spot light's factor at cos(theta) from its axis, by its falloff model
// (Light::falloff): 0 outside the cone of cutoffDegrees.
double spotFactor(const Light& light, double cosTheta);

// Kircher-Lawrance normal transform, exact.
glm::dvec2 encodeNormalKL(const glm::dvec3& n);
glm::dvec3 decodeNormalKL(const glm::dvec2& e);
// Octahedral normal (Cigolle et al. 2014, section 3.3; shaders/common/gbuffer.glsl), exact.
glm::dvec2 encodeNormalOct(const glm::dvec3& n);
glm::dvec3 decodeNormalOct(const glm::dvec2& e);

}  // namespace dw::reference
