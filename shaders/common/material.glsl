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
};

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
