#include "renderer/reference/SkyReference.h"

#include <algorithm>
#include <cmath>

namespace dw::reference {

namespace {

constexpr double kPi = 3.14159265358979323846;

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

glm::dvec3 texelOf(const FloatImage& img, int x, int y) {
    const float* p = &img.pixels[(static_cast<size_t>(y) * img.width + x) * img.channels];
    return img.channels >= 3 ? glm::dvec3(p[0], p[1], p[2]) : glm::dvec3(p[0]);
}

// Bilinear at texture coordinate (u, v), rows top-down; u wraps or clamps.
glm::dvec3 bilinear(const FloatImage& img, double u, double v, bool repeatU) {
    if (img.width <= 0 || img.height <= 0) return glm::dvec3(0.0);
    const double x = u * img.width - 0.5, y = v * img.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double ax = x - fx, ay = y - fy;
    auto cx = [&](double i) {
        long long k = static_cast<long long>(i);
        if (repeatU) {
            k %= img.width;
            return static_cast<int>(k < 0 ? k + img.width : k);
        }
        return static_cast<int>(std::clamp<long long>(k, 0, img.width - 1));
    };
    auto cy = [&](double i) { return static_cast<int>(std::clamp<long long>(static_cast<long long>(i), 0, img.height - 1)); };
    const int x0 = cx(fx), x1 = cx(fx + 1), y0 = cy(fy), y1 = cy(fy + 1);
    return glm::mix(glm::mix(texelOf(img, x0, y0), texelOf(img, x1, y0), ax),
                    glm::mix(texelOf(img, x0, y1), texelOf(img, x1, y1), ax), ay);
}

}  // namespace

SkyReference::SkyReference(const Scene& scene, const ReferenceModel& model)
    : scene_(scene), kind_(model.sky), intensity_(model.skyIntensity), rotation_(model.skyRotationDegrees * kPi / 180.0) {
    cosSunRadius_ = std::cos(scene.sky.sunSizeDegrees * 0.5 * kPi / 180.0);
    for (const Light& l : scene.lights)
        if (l.enabled && l.type == LightType::Directional) {
            hasSun_ = true;
            sunDirection_ = -glm::normalize(glm::dvec3(l.direction));
            sunColor_ = glm::dvec3(l.intensity) * 40.0;
            break;
        }
}

glm::dvec3 SkyReference::procedural(const glm::dvec3& d) const {
    const Sky& s = scene_.sky;
    const double e = d.y;
    glm::dvec3 c = e >= 0.0 ? glm::mix(glm::dvec3(s.horizon), glm::dvec3(s.zenith), std::pow(e, 0.45))
                            : glm::mix(glm::dvec3(s.horizon), glm::dvec3(s.ground), std::pow(std::min(-e * 4.0, 1.0), 0.6));
    if (hasSun_) {
        const double cosA = glm::dot(d, sunDirection_);
        const double disc = smoothstep(cosSunRadius_ - 0.00002, cosSunRadius_ + 0.00002, cosA);
        const double glow = std::pow(std::max(cosA, 0.0), 48.0) * 0.02 + std::pow(std::max(cosA, 0.0), 6.0) * 0.004;
        c += sunColor_ * (disc + glow);
    }
    return c;
}

glm::dvec3 SkyReference::radiance(const glm::dvec3& d) const {
    if (kind_ == SkyChoice::Color) return glm::dvec3(scene_.background);
    const double r = rotation_;
    const glm::dvec3 dr(std::cos(r) * d.x + std::sin(r) * d.z, d.y, -std::sin(r) * d.x + std::cos(r) * d.z);
    glm::dvec3 c;
    if (kind_ == SkyChoice::Equirect) {
        const double u = 0.5 + std::atan2(dr.x, -dr.z) / (2.0 * kPi);
        const double v = std::acos(std::clamp(dr.y, -1.0, 1.0)) / kPi;
        c = bilinear(scene_.sky.equirect, u, v, true);
    } else if (kind_ == SkyChoice::Cube) {
        // OpenGL's cube-map face selection (GL 4.5 spec, table 8.19), faces +X -X +Y -Y +Z -Z.
        const glm::dvec3 a = glm::abs(dr);
        int face;
        double sc, tc, ma;
        if (a.x >= a.y && a.x >= a.z) {
            face = dr.x > 0 ? 0 : 1;
            ma = a.x;
            sc = dr.x > 0 ? -dr.z : dr.z;
            tc = -dr.y;
        } else if (a.y >= a.z) {
            face = dr.y > 0 ? 2 : 3;
            ma = a.y;
            sc = dr.x;
            tc = dr.y > 0 ? dr.z : -dr.z;
        } else {
            face = dr.z > 0 ? 4 : 5;
            ma = a.z;
            sc = dr.z > 0 ? dr.x : -dr.x;
            tc = -dr.y;
        }
        // (s, t) with t = 0 at the first row uploaded (GL's face images are
        // given with t growing downwards as these images' rows do).
        c = bilinear(scene_.sky.cubeFaces[face], 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0), false);
    } else {
        c = procedural(d);
    }
    c *= intensity_;
    for (int i = 0; i < 3; ++i) c[i] = std::isnan(c[i]) ? 0.0 : std::max(c[i], 0.0);
    return c;
}

}  // namespace dw::reference
