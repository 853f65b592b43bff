// The L-buffer's first write at a pixel, before any light is added: the sky
// (or the background colour) where no geometry is, else the ambient term
// k_a i_a (seed 000 eq. 2.1; k_a = diffuse, plus specular when
// lighting.ambient_specular is on) scaled by the ambient-occlusion
// accessibility, plus emitted radiance. The accessibility is the product of
// the screen-space one (ao.filtered, when it ran) and the materials' baked
// one (gbuffer.occlusion), as lighting.ambient_occlusion selects. With
// lighting.directional_in_gbuffer the directional lights the G-buffer pass
// shaded (gbuffer.directional) are added here instead of a full-screen pass
// each. Written by ambient.frag, or by a strategy whose own pass makes the
// first write (tiled.comp: LightingStrategy::writesFirstRadiance).
// With gtao.multibounce (ao.method = gtao) the accessibility x becomes, per
// colour channel with the diffuse albedo rho, Jimenez et al. 2016's fit of
// the light that interreflections bring back (the paper's multi-bounce approximation):
//     max(x, ((a x + b) x + c) x),  a = 2.0404 rho - 0.3324,
//     b = -4.7951 rho + 0.6417,      c = 2.7552 rho + 0.6903,
// clamped to 1 (a + b + c = 0.9996 + 0.0005 rho: 1 stays 1).
#ifndef AMBIENT_GLSL
#define AMBIENT_GLSL
#include "../common/bindings.glsl"
#include "gbuffer_read.glsl"
#include "../params/lighting.h"

layout(binding = AMBIENT_SKY_TEXTURE) uniform sampler2D uSky;                      // when lightingParams.sky != 0
layout(binding = AMBIENT_BAKED_OCCLUSION_TEXTURE) uniform sampler2D uBakedOcclusion;          // gbuffer.occlusion
layout(binding = AMBIENT_GBUFFER_DIRECTIONAL_TEXTURE) uniform sampler2D uGBufferDirectionalLight;  // when lightingParams.gbufferDirectional != 0

vec3 gtaoMultiBounce(float x, vec3 albedo) {
    vec3 a = 2.0404 * albedo - 0.3324;
    vec3 b = -4.7951 * albedo + 0.6417;
    vec3 c = 2.7552 * albedo + 0.6903;
    return min(max(vec3(x), ((x * a + b) * x + c) * x), vec3(1.0));
}

vec3 firstRadiance(ivec2 px, Surface s) {
    vec3 background = lightingParams.sky != 0 ? texelFetch(uSky, px, 0).rgb : lightingParams.background.rgb;
    float access = lightingParams.occlusion != 0 ? texelFetch(uOcclusion, px, 0).r : 1.0;
    if (lightingParams.bakedOcclusion != 0) access *= texelFetch(uBakedOcclusion, px, 0).r;
    vec3 emitted = texelFetch(uEmissive, px, 0).rgb;
    vec3 reflectance = s.diffuse + (lightingParams.ambientSpecular != 0 ? s.specular : vec3(0.0));
    vec3 directional =
        lightingParams.gbufferDirectional != 0 ? texelFetch(uGBufferDirectionalLight, px, 0).rgb : vec3(0.0);
    vec3 accessRgb = lightingParams.multiBounce != 0 ? gtaoMultiBounce(access, clamp(s.diffuse, 0.0, 1.0)) : vec3(access);
    vec3 lit = lightingParams.ambient.rgb * reflectance * accessRgb + emitted + directional;
    return isFarDepth(s.depth) || s.pixelType == PIXEL_BACKGROUND ? background : lit;
}

#endif
