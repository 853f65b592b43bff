// A material's Blinn-Phong terms at a fragment (material.glsl's models mapped
// to diffuse, specular colour and exponent, with the normal map applied): what
// the G-buffer pass encodes (geometry.frag) and what the forward lighting
// strategies shade directly (lighting/forward.frag), so the two see the same
// inputs up to the G-buffer's quantisation.
#ifndef MATERIAL_EVAL_GLSL
#define MATERIAL_EVAL_GLSL
#include "bindings.glsl"
#include "material.glsl"

layout(binding = MATERIAL_BASE_COLOR_TEXTURE) uniform sampler2D uBaseColorMap;
layout(binding = MATERIAL_NORMAL_TEXTURE) uniform sampler2D uNormalMap;
layout(binding = MATERIAL_SPECULAR_TEXTURE) uniform sampler2D uSpecularMap;
layout(binding = MATERIAL_EMISSIVE_TEXTURE) uniform sampler2D uEmissiveMap;
layout(binding = MATERIAL_OCCLUSION_TEXTURE) uniform sampler2D uOcclusionMap;  // GpuScene::kOcclusionUnit

struct MaterialSample {
    vec3 normal;  // view space, normal map applied, facing the viewer on double-sided back faces
    vec3 diffuse;
    vec3 specular;
    float exponent;
    vec3 emissive;
};

// False where an alpha-masked material cuts the fragment out (discard it).
// uvs: every texture slot's coordinates (material.glsl's materialUvs, in the
// vertex shader); color: COLOR_0 (white when absent), which multiplies the
// base colour (glTF 2.0, "Metallic-Roughness Material").
bool evaluateMaterial(Material m, vec3 normal, vec4 tangent, vec2 uvs[MATERIAL_SLOTS], vec4 color, bool frontFacing,
                      out MaterialSample ms) {
    vec4 base = m.baseColor * color;
    if (m.textures.x != 0) base *= texture(uBaseColorMap, uvs[SLOT_BASE_COLOR]);
    if (m.flags.y == ALPHA_MASK && base.a < m.params.w) return false;

    vec3 N = normalize(normal);
    if (!frontFacing) N = -N;  // double-sided materials: shade the side we see
    if (m.textures.y != 0) {
        vec3 T = tangent.xyz - N * dot(N, tangent.xyz);
        float tl = length(T);
        if (tl > 1e-6) {
            T /= tl;
            vec3 B = cross(N, T) * (tangent.w < 0.0 ? -1.0 : 1.0);
            if (!frontFacing) B = -B;
            vec3 t = texture(uNormalMap, uvs[SLOT_NORMAL]).xyz * 2.0 - 1.0;
            t.xy *= m.emissive.a;
            N = normalize(mat3(T, B, N) * t);
        }
    }
    ms.normal = N;

    vec4 s = m.textures.z != 0 ? texture(uSpecularMap, uvs[SLOT_SPECULAR]) : vec4(1.0);
    if (m.flags.x == MODEL_METALLIC_ROUGHNESS) {
        float metallic = clamp(m.params.x * s.b, 0.0, 1.0);
        float roughness = clamp(m.params.y * s.g, 0.0, 1.0);
        ms.diffuse = base.rgb * (1.0 - metallic);
        ms.exponent = roughnessToExponent(roughness);
        ms.specular = normalisedSpecular(mix(m.specular.rgb, base.rgb, metallic), ms.exponent);
    } else if (m.flags.x == MODEL_SPECULAR_GLOSSINESS) {
        ms.diffuse = base.rgb;
        ms.exponent = roughnessToExponent(1.0 - clamp(m.params.z * s.a, 0.0, 1.0));
        ms.specular = normalisedSpecular(m.specular.rgb * s.rgb, ms.exponent);
    } else {
        ms.diffuse = base.rgb;
        ms.specular = m.specular.rgb * s.rgb;
        ms.exponent = m.specular.a;
    }
    ms.emissive = m.emissive.rgb;
    if (m.textures.w != 0) ms.emissive *= texture(uEmissiveMap, uvs[SLOT_EMISSIVE]).rgb;
    return true;
}

// Baked ambient accessibility (glTF occlusionTexture): 1 + strength * (R - 1), 1 without a texture.
float materialOcclusion(Material m, vec2 uvs[MATERIAL_SLOTS]) {
    if (m.occlusion.x == 0.0) return 1.0;
    float r = texture(uOcclusionMap, uvs[SLOT_OCCLUSION]).r;
    return clamp(1.0 + m.occlusion.y * (r - 1.0), 0.0, 1.0);
}

#endif
