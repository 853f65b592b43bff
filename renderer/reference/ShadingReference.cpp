#include "renderer/reference/ShadingReference.h"

#include <algorithm>
#include <cmath>

namespace dw::reference {

double attenuation(const Attenuation& a, double d, double radius, AttenuationModel model, double windowExponent) {
    if (radius > 0.0 && d > radius) return 0.0;
    double att = 1.0 / std::max(a.constant + a.linear * d + a.quadratic * d * d, 1e-6);
    if (model == AttenuationModel::Windowed && radius > 0.0) att *= 1.0 - std::pow(d / radius, windowExponent);
    return att;
}

double spotFactor(const Light& light, double cosTheta) {
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    const double cosOuter = std::cos(light.cutoffDegrees * kDegree);
    if (!(cosTheta >= cosOuter)) return 0.0;
    if (light.falloff == SpotFalloff::CutoffExponent)
        return std::pow(std::max(cosTheta, 0.0), static_cast<double>(light.exponent));
    const double cosInner = std::cos(light.innerConeDegrees * kDegree);
    if (cosInner <= cosOuter) return cosTheta > cosOuter ? 1.0 : 0.0;
    const double t = std::clamp((cosTheta - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    return t * t;
}

glm::dvec3 shadeLight(const Light& light, const glm::dvec3& lightPosition, const glm::dvec3& lightDirection,
                      double radius, const SurfacePoint& s, AttenuationModel model, double windowExponent) {
    glm::dvec3 L;
    double scale = 1.0;
    if (light.type == LightType::Directional) {
        L = -glm::normalize(lightDirection);
    } else {
        const glm::dvec3 toLight = lightPosition - s.position;
        const double d = glm::length(toLight);
        L = toLight / std::max(d, 1e-12);
        scale = attenuation(light.attenuation, d, radius, model, windowExponent);
        if (light.type == LightType::Spot) {
            scale *= spotFactor(light, glm::dot(-L, glm::normalize(lightDirection)));
        }
    }
    const double nDotL = glm::dot(s.normal, L);
    if (scale <= 0.0 || nDotL <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 V = glm::normalize(-s.position);
    const glm::dvec3 H = glm::normalize(L + V);
    const double spec = std::pow(std::max(glm::dot(s.normal, H), 0.0), s.exponent);
    return glm::dvec3(light.intensity) * scale * (s.diffuse * nDotL + s.specular * spec);
}

glm::dvec2 encodeNormalKL(const glm::dvec3& n) {
    const glm::dvec3 m(n.x, n.y, n.z + 1.0);
    const double len = glm::length(m);
    return len > 1e-15 ? glm::dvec2(m) / len : glm::dvec2(1.0, 0.0);
}

glm::dvec3 decodeNormalKL(const glm::dvec2& e) {
    const double z = std::sqrt(std::max(1.0 - glm::dot(e, e), 0.0));
    return {2.0 * z * e.x, 2.0 * z * e.y, 2.0 * z * z - 1.0};
}

namespace {
glm::dvec2 signNotZero(const glm::dvec2& v) { return {v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0}; }
}  // namespace

glm::dvec2 encodeNormalOct(const glm::dvec3& n) {
    const glm::dvec2 p = glm::dvec2(n) / (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
    return n.z <= 0.0 ? (1.0 - glm::abs(glm::dvec2(p.y, p.x))) * signNotZero(p) : p;
}

glm::dvec3 decodeNormalOct(const glm::dvec2& e) {
    glm::dvec3 v(e, 1.0 - std::abs(e.x) - std::abs(e.y));
    if (v.z < 0.0) {
        const glm::dvec2 folded = (1.0 - glm::abs(glm::dvec2(v.y, v.x))) * signNotZero(glm::dvec2(v));
        v.x = folded.x;
        v.y = folded.y;
    }
    return glm::normalize(v);
}

}  // namespace dw::reference
