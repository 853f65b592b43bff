#version 450 core
// G-buffer pass (seed 000, section 5.2, listing 5.5): writes albedo + pixel
// type, the encoded view-space normal, specular colour + exponent, the
// emitted radiance and the material's baked ambient occlusion. Material models are mapped to Blinn-Phong by
// common/material_eval.glsl (shared with the forward lighting strategies).
#include "common/gbuffer.glsl"
#include "common/material_eval.glsl"

layout(location = 1) uniform int uMaterial;

#ifdef DIRECTIONAL_IN_GBUFFER
// lighting.directional_in_gbuffer (seed 000 section 3.2.1): the directional
// lights without a shadow map shaded here, from the unquantised material, so
// the lighting pass needs no full-screen pass for them; it adds
// gbuffer.directional in its first (ambient) write.
#include "common/lighting.glsl"
#define MAX_GBUFFER_DIRECTIONAL 8  // kMaxGBufferDirectional
layout(location = 2) uniform int uDirectionalCount;
layout(location = 3) uniform int uDirectional[MAX_GBUFFER_DIRECTIONAL];  // light-table rows
layout(location = 5) out vec4 outDirectional;
#endif

in VertexData {
    vec3 viewPosition;
    vec3 normal;
    vec4 tangent;
    vec2 uvs[MATERIAL_SLOTS];
    vec4 color;
} fs;

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec2 outNormal;
layout(location = 2) out vec4 outSpecular;
layout(location = 3) out vec4 outEmissive;
layout(location = 4) out float outOcclusion;

void main() {
    MaterialSample ms;
    if (!evaluateMaterial(materials[uMaterial], fs.normal, fs.tangent, fs.uvs, fs.color, gl_FrontFacing, ms)) discard;
    outAlbedo = vec4(clamp(ms.diffuse, 0.0, 1.0), PIXEL_SURFACE / 255.0);
    outNormal = encodeNormal(ms.normal);
    outSpecular = vec4(clamp(ms.specular, 0.0, 1.0), encodeExponent(ms.exponent));
    outEmissive = vec4(clamp(ms.emissive, vec3(0.0), vec3(65000.0)), 0.0);  // R11G11B10F's largest value: stay finite
    outOcclusion = materialOcclusion(materials[uMaterial], fs.uvs);
#ifdef DIRECTIONAL_IN_GBUFFER
    // The terms the G-buffer stores (clamped to [0, 1] as stored), unquantised.
    vec3 sum = vec3(0.0);
    for (int i = 0; i < uDirectionalCount; ++i)
        sum += shadeLight(lights[uDirectional[i]], fs.viewPosition, ms.normal, clamp(ms.diffuse, 0.0, 1.0),
                          clamp(ms.specular, 0.0, 1.0), ms.exponent, false, 1.0);
    outDirectional = vec4(sum, 0.0);
#endif
}
