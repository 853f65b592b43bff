#include "renderer/reference/MaterialEvaluator.h"

#include <algorithm>
#include <cmath>

#include "renderer/reference/TextureSampler.h"
#include "renderer/scene/SceneCheck.h"

namespace dw::reference {

namespace {

// material.glsl's roughnessToExponent: a GGX/Beckmann lobe's width as a
// Blinn-Phong exponent (alpha = r^2, n = 2 / alpha^2 - 2), in [1, 2048].
double roughnessToExponent(double roughness) {
    const double a = std::max(roughness * roughness, 1e-3);
    return std::clamp(2.0 / (a * a) - 2.0, 1.0, 2048.0);
}

// material.glsl's normalisedSpecular.
glm::dvec3 normalisedSpecular(const glm::dvec3& f0, double exponent) {
    const double peak = std::max(std::max(f0.r, f0.g), std::max(f0.b, 1e-6));
    return f0 * std::min((exponent + 8.0) / 8.0, 1.0 / peak);
}

template <typename T>
T interpolate(const std::vector<T>& a, const glm::uvec3& t, double u, double v) {
    return (1.0 - u - v) * a[t.x] + u * a[t.y] + v * a[t.z];
}

}  // namespace

SurfaceSample evaluateSurface(const Scene& scene, const RayScene& rays, const RayHit& hit, const glm::dvec3& org,
                              const glm::dvec3& dir) {
    (void)org;
    const InstanceGeometry& g = rays.instances()[hit.instance];
    const Material& m = scene.materials[g.material];
    const auto& images = scene.images;
    const glm::uvec3 t = rays.triangle(hit.instance, hit.triangle);
    const double u = hit.u, v = hit.v;
    SurfaceSample s;
    s.position = interpolate(g.positions, t, u, v);

    glm::dvec3 ng = glm::cross(g.positions[t.y] - g.positions[t.x], g.positions[t.z] - g.positions[t.x]);
    if (g.mirrored) ng = -ng;
    const double ngLength = glm::length(ng);
    ng = ngLength > 0.0 ? ng / ngLength : -glm::normalize(dir);
    const bool frontFacing = glm::dot(ng, dir) <= 0.0;
    s.geometricNormal = frontFacing ? ng : -ng;

    const glm::dvec2 uv0 = interpolate(g.uv0, t, u, v), uv1 = interpolate(g.uv1, t, u, v);
    auto uvFor = [&](int slot) { return transformUv(m.mapping[slot], m.mapping[slot].texCoord == 1 ? uv1 : uv0); };
    auto sample = [&](int image, int slot, bool srgb) {
        return sampleBilinear(images[image], m.mapping[slot], uvFor(slot), srgb);
    };

    glm::dvec4 base = glm::dvec4(m.baseColor) * interpolate(g.colors, t, u, v);
    if (m.baseColorTexture >= 0) base *= sample(m.baseColorTexture, Material::BaseColorSlot, true);
    s.alpha = std::clamp(base.a, 0.0, 1.0);

    glm::dvec3 N = interpolate(g.normals, t, u, v);
    const double nLength = glm::length(N);
    N = nLength > 0.0 ? N / nLength : ng;
    if (!frontFacing) N = -N;
    if (m.normalTexture >= 0) {
        const glm::dvec4 tangent = interpolate(g.tangents, t, u, v);
        glm::dvec3 T = glm::dvec3(tangent) - N * glm::dot(N, glm::dvec3(tangent));
        const double tl = glm::length(T);
        if (tl > 1e-6) {
            T /= tl;
            // The bitangent sign is the vertex's (interpolated), times the
            // instance's mirroring as the GPU's model-view transform gives it.
            double sign = tangent.w < 0.0 ? -1.0 : 1.0;
            if (g.mirrored) sign = -sign;
            glm::dvec3 B = glm::cross(N, T) * sign;
            if (!frontFacing) B = -B;
            glm::dvec3 n = glm::dvec3(sample(m.normalTexture, Material::NormalSlot, false)) * 2.0 - 1.0;
            n.x *= m.normalScale;
            n.y *= m.normalScale;
            const glm::dvec3 mapped = T * n.x + B * n.y + N * n.z;
            const double ml = glm::length(mapped);
            if (ml > 0.0) N = mapped / ml;
        }
    }
    s.normal = N;

    const int specularImage = m.model == MaterialModel::MetallicRoughness ? m.metallicRoughnessTexture : m.specularTexture;
    const glm::dvec4 spec = specularImage >= 0
                                ? sample(specularImage, Material::SpecularSlot, m.model == MaterialModel::SpecularGlossiness)
                                : glm::dvec4(1.0);
    glm::dvec3 diffuse, specular;
    double exponent;
    if (m.model == MaterialModel::MetallicRoughness) {
        const double metallic = std::clamp(m.metallic * spec.b, 0.0, 1.0);
        const double roughness = std::clamp(m.roughness * spec.g, 0.0, 1.0);
        diffuse = glm::dvec3(base) * (1.0 - metallic);
        exponent = roughnessToExponent(roughness);
        specular = normalisedSpecular(glm::mix(glm::dvec3(m.specularColor), glm::dvec3(base), metallic), exponent);
    } else if (m.model == MaterialModel::SpecularGlossiness) {
        diffuse = glm::dvec3(base);
        exponent = roughnessToExponent(1.0 - std::clamp(m.glossiness * spec.a, 0.0, 1.0));
        specular = normalisedSpecular(glm::dvec3(m.specularColor) * glm::dvec3(spec), exponent);
    } else {
        diffuse = glm::dvec3(base);
        specular = glm::dvec3(m.specularColor) * glm::dvec3(spec);
        exponent = m.specularExponent;
    }
    // The G-buffer's ranges (geometry.frag, gbuffer.glsl's encodeExponent).
    s.diffuse = glm::clamp(diffuse, 0.0, 1.0);
    s.specular = glm::clamp(specular, 0.0, 1.0);
    s.exponent = std::clamp(std::isfinite(exponent) ? exponent : 1.0, 1.0, 2048.0);
    glm::dvec3 emissive(m.emissive);
    if (m.emissiveTexture >= 0) emissive *= glm::dvec3(sample(m.emissiveTexture, Material::EmissiveSlot, true));
    s.emissive = glm::clamp(emissive, 0.0, double(kMaxEmission));  // as the GPU clamps it, opaque or blended
    if (m.occlusionTexture >= 0) {
        const double r = sample(m.occlusionTexture, Material::OcclusionSlot, false).r;
        s.occlusion = std::clamp(1.0 + m.occlusionStrength * (r - 1.0), 0.0, 1.0);
    }
    return s;
}

}  // namespace dw::reference
