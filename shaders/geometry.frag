#version 450 core
// G-buffer pass (seed 000, section 5.2, listing 5.5): writes albedo + pixel
// type, the encoded view-space normal, specular colour + exponent and the
// emitted radiance. Material models are mapped to Blinn-Phong by
// common/material_eval.glsl (shared with the forward lighting strategies).
#include "common/gbuffer.glsl"
#include "common/material_eval.glsl"

layout(location = 1) uniform int uMaterial;

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
    MaterialSample ms;
    if (!evaluateMaterial(materials[uMaterial], fs.normal, fs.tangent, fs.uv, gl_FrontFacing, ms)) discard;
    outAlbedo = vec4(clamp(ms.diffuse, 0.0, 1.0), PIXEL_SURFACE / 255.0);
    outNormal = encodeNormalKL(ms.normal);
    outSpecular = vec4(clamp(ms.specular, 0.0, 1.0), encodeExponent(ms.exponent));
    outEmissive = vec4(clamp(ms.emissive, vec3(0.0), vec3(65000.0)), 0.0);  // R11G11B10F's largest value: stay finite
}
