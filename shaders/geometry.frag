#version 450 core
// G-buffer pass (seed 000, section 5.2, listing 5.5): writes albedo + pixel
// type, the encoded view-space normal, specular colour + exponent and the
// emitted radiance. Material models are mapped to Blinn-Phong here.
#include "common/gbuffer.glsl"
#include "common/material.glsl"

layout(location = 1) uniform int uMaterial;

layout(binding = 0) uniform sampler2D uBaseColorMap;
layout(binding = 1) uniform sampler2D uNormalMap;
layout(binding = 2) uniform sampler2D uSpecularMap;
layout(binding = 3) uniform sampler2D uEmissiveMap;

in VertexData {
    vec3 viewPosition;
    vec3 normal;
    vec4 tangent;
    vec2 uv;
} fs;

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec2 outNormal;
layout(location = 2) out vec4 outSpecular;
layout(location = 3) out vec4 outEmissive;

void main() {
    Material m = materials[uMaterial];
    vec4 base = m.baseColor;
    if (m.textures.x != 0) base *= texture(uBaseColorMap, fs.uv);
    if (m.flags.y == ALPHA_MASK && base.a < m.params.w) discard;

    vec3 N = normalize(fs.normal);
    if (!gl_FrontFacing) N = -N;  // double-sided materials: shade the side we see
    if (m.textures.y != 0) {
        vec3 T = fs.tangent.xyz - N * dot(N, fs.tangent.xyz);
        float tl = length(T);
        if (tl > 1e-6) {
            T /= tl;
            vec3 B = cross(N, T) * (fs.tangent.w < 0.0 ? -1.0 : 1.0);
            if (!gl_FrontFacing) B = -B;
            vec3 t = texture(uNormalMap, fs.uv).xyz * 2.0 - 1.0;
            t.xy *= m.emissive.a;
            N = normalize(mat3(T, B, N) * t);
        }
    }

    vec3 diffuse;
    vec3 specular;
    float exponent;
    vec4 s = m.textures.z != 0 ? texture(uSpecularMap, fs.uv) : vec4(1.0);
    if (m.flags.x == MODEL_METALLIC_ROUGHNESS) {
        float metallic = clamp(m.params.x * s.b, 0.0, 1.0);
        float roughness = clamp(m.params.y * s.g, 0.0, 1.0);
        diffuse = base.rgb * (1.0 - metallic);
        exponent = roughnessToExponent(roughness);
        specular = normalisedSpecular(mix(m.specular.rgb, base.rgb, metallic), exponent);
    } else if (m.flags.x == MODEL_SPECULAR_GLOSSINESS) {
        diffuse = base.rgb;
        exponent = roughnessToExponent(1.0 - clamp(m.params.z * s.a, 0.0, 1.0));
        specular = normalisedSpecular(m.specular.rgb * s.rgb, exponent);
    } else {
        diffuse = base.rgb;
        specular = m.specular.rgb * s.rgb;
        exponent = m.specular.a;
    }
    vec3 emissive = m.emissive.rgb;
    if (m.textures.w != 0) emissive *= texture(uEmissiveMap, fs.uv).rgb;

    outAlbedo = vec4(clamp(diffuse, 0.0, 1.0), PIXEL_SURFACE / 255.0);
    outNormal = encodeNormalKL(N);
    outSpecular = vec4(clamp(specular, 0.0, 1.0), encodeExponent(exponent));
    outEmissive = vec4(max(emissive, vec3(0.0)), 0.0);
}
