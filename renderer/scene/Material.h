#pragma once
// Surface description. The G-buffer stores Blinn-Phong terms (diffuse colour,
// specular colour, specular exponent); glTF's metallic-roughness and
// specular-glossiness materials are mapped to them per pixel in
// shaders/geometry.frag, as docs/scene-format.md describes.
#include <glm/glm.hpp>
#include <string>

namespace dw {

enum class AlphaMode { Opaque, Mask, Blend };
enum class MaterialModel { BlinnPhong, MetallicRoughness, SpecularGlossiness };

struct Material {
    std::string name;
    MaterialModel model = MaterialModel::BlinnPhong;
    glm::vec4 baseColor{0.8f, 0.8f, 0.8f, 1.0f};  // linear; diffuse colour (and alpha)
    int baseColorTexture = -1;                    // index into Scene::images, sRGB
    // Blinn-Phong / specular-glossiness specular colour. For metallic-roughness
    // this is the dielectric F0 (0.04, or KHR_materials_specular's value).
    glm::vec3 specularColor{0.04f};
    float specularExponent = 32.0f;  // Blinn-Phong
    float glossiness = 1.0f;         // specular-glossiness
    int specularTexture = -1;        // rgb specular colour (x factor), a glossiness / exponent scale
    float metallic = 1.0f;           // metallic-roughness
    float roughness = 1.0f;
    int metallicRoughnessTexture = -1;  // glTF: G roughness, B metallic
    int normalTexture = -1;
    float normalScale = 1.0f;
    glm::vec3 emissive{0.0f};
    int emissiveTexture = -1;  // sRGB
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

}  // namespace dw
