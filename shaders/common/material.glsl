// Material table (dw::GpuScene's MaterialGpu, std430) and the mapping of every
// material model to the Blinn-Phong terms the G-buffer stores
// (docs/scene-format.md, "Materials").
#include "bindings.glsl"

#define MODEL_BLINN_PHONG 0
#define MODEL_METALLIC_ROUGHNESS 1
#define MODEL_SPECULAR_GLOSSINESS 2
#define ALPHA_OPAQUE 0
#define ALPHA_MASK 1
#define ALPHA_BLEND 2

struct Material {
    vec4 baseColor;
    vec4 specular;   // rgb specular colour or dielectric F0, a exponent
    vec4 emissive;   // rgb emissive, a normal scale
    vec4 params;     // metallic, roughness, glossiness, alpha cutoff
    ivec4 textures;  // has base colour, normal, specular/MR, emissive
    ivec4 flags;     // model, alpha mode, double sided
    ivec4 texCoords; // UV set (0, 1) of base colour, normal, specular/MR, emissive
    vec4 occlusion;  // has occlusion texture, strength, UV set
    vec4 uvTransform[10];  // per slot (base colour, normal, specular/MR, emissive, occlusion): rows of the 2x3 UV transform
};

#define SLOT_BASE_COLOR 0
#define SLOT_NORMAL 1
#define SLOT_SPECULAR 2
#define SLOT_EMISSIVE 3
#define SLOT_OCCLUSION 4

#define MATERIAL_SLOTS 5

// The texture coordinates of every slot: its UV set (texCoords, occlusion.z)
// through its KHR_texture_transform matrix (identity when the file has none).
// Evaluated per vertex, so the fragment shader samples interpolated UVs:
// implicit derivatives come from helper invocations, which need not load
// buffer memory (llvmpipe masks it), so a transform read from this SSBO in
// the fragment shader chose wrong mip levels along every triangle edge.
void materialUvs(Material m, vec2 uv0, vec2 uv1, out vec2 uvs[MATERIAL_SLOTS]) {
    int sets[MATERIAL_SLOTS] = int[](m.texCoords.x, m.texCoords.y, m.texCoords.z, m.texCoords.w, int(m.occlusion.z));
    for (int slot = 0; slot < MATERIAL_SLOTS; ++slot) {
        vec3 uv = vec3(sets[slot] == 1 ? uv1 : uv0, 1.0);
        uvs[slot] = vec2(dot(m.uvTransform[2 * slot].xyz, uv), dot(m.uvTransform[2 * slot + 1].xyz, uv));
    }
}

layout(std430, binding = MATERIAL_SSBO) readonly buffer MaterialTable {
    Material materials[];
};

// Blinn-Phong exponent with the highlight width of a GGX/Beckmann lobe of the
// given perceptual roughness: alpha = r^2, n = 2 / alpha^2 - 2 (Walter et al. 2007).
float roughnessToExponent(float roughness) {
    float a = max(roughness * roughness, 1e-3);
    return clamp(2.0 / (a * a) - 2.0, 1.0, 2048.0);
}

// The unnormalised Blinn-Phong lobe peaks at 1; scaling by (n + 8) / 8 gives it
// roughly the energy of the normalised lobe, so a glossy PBR material keeps a
// visible highlight. Limited so the largest channel is 1 (the G-buffer stores
// [0, 1]), which keeps the hue of coloured metals.
vec3 normalisedSpecular(vec3 f0, float exponent) {
    float peak = max(max(f0.r, f0.g), max(f0.b, 1e-6));
    return f0 * min((exponent + 8.0) / 8.0, 1.0 / peak);
}
