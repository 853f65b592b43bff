// Reads and decodes the G-buffer at a pixel, for the lighting passes.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/gbuffer.glsl"

layout(binding = GBUFFER_ALBEDO_TEXTURE) uniform sampler2D uAlbedo;
layout(binding = GBUFFER_NORMAL_TEXTURE) uniform sampler2D uNormal;
layout(binding = GBUFFER_SPECULAR_TEXTURE) uniform sampler2D uSpecular;
layout(binding = GBUFFER_EMISSIVE_TEXTURE) uniform sampler2D uEmissive;
layout(binding = GBUFFER_DEPTH_TEXTURE) uniform sampler2D uDepth;
layout(binding = LIGHTING_OCCLUSION_TEXTURE) uniform sampler2D uOcclusion;

struct Surface {
    float depth;
    float pixelType;
    vec3 position;  // view space
    vec3 normal;    // view space
    vec3 diffuse;
    vec3 specular;
    float exponent;
};

Surface readSurface(ivec2 px) {
    Surface s;
    s.depth = texelFetch(uDepth, px, 0).r;
    vec4 albedo = texelFetch(uAlbedo, px, 0);
    vec4 spec = texelFetch(uSpecular, px, 0);
    s.pixelType = floor(albedo.a * 255.0 + 0.5);
    s.position = viewPositionAtPixel(px, s.depth);
    s.normal = decodeNormal(texelFetch(uNormal, px, 0).xy);
    s.diffuse = albedo.rgb;
    s.specular = spec.rgb;
    s.exponent = decodeExponent(spec.a);
    return s;
}
