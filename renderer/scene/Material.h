#pragma once
// Surface description. The G-buffer stores Blinn-Phong terms (diffuse colour,
// specular colour, specular exponent); glTF's metallic-roughness and
// specular-glossiness materials are mapped to them per pixel in
// shaders/geometry.frag, as docs/scene-format.md describes.
#include <glm/glm.hpp>
#include <string>

namespace dw {

enum class AlphaMode { Opaque, Mask, Blend };

// How a material reads one of its textures: the glTF textureInfo's UV set,
// its sampler (GL enums, glTF 2.0 "Samplers"; defaults: repeat, trilinear)
// and KHR_texture_transform's offset, rotation (radians) and scale, applied
// as uv' = T * R * S * uv with the extension's rotation sense.
struct TextureMapping {
    int texCoord = 0;               // 0: TEXCOORD_0, 1: TEXCOORD_1
    unsigned wrapS = 0x2901;        // GL_REPEAT, GL_CLAMP_TO_EDGE or GL_MIRRORED_REPEAT
    unsigned wrapT = 0x2901;
    unsigned minFilter = 0x2703;    // GL_LINEAR_MIPMAP_LINEAR
    unsigned magFilter = 0x2601;    // GL_LINEAR
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;
    glm::vec2 scale{1.0f};
    // The 2x3 affine matrix as two rows (u' = row0 . (u, v, 1), v' = row1 . (u, v, 1)).
    glm::vec3 row(int r) const;
};
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
    // Baked ambient occlusion (glTF occlusionTexture, R channel): ambient
    // accessibility 1 + strength * (R - 1), written to gbuffer.occlusion.
    int occlusionTexture = -1;
    float occlusionStrength = 1.0f;
    // Sampling of baseColorTexture, normalTexture, specular / metallic-roughness,
    // emissiveTexture and occlusionTexture, in that order.
    enum Slot { BaseColorSlot, NormalSlot, SpecularSlot, EmissiveSlot, OcclusionSlot, kSlotCount };
    TextureMapping mapping[kSlotCount];
};

}  // namespace dw
