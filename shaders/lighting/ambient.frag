#version 450 core
// First write of the L-buffer: the sky (or the background colour) where no
// geometry is, else the
// ambient term k_a i_a (seed 000 eq. 2.1; k_a = diffuse, plus specular when
// lighting.ambient_specular is on) scaled by the ambient-occlusion
// accessibility, plus emitted radiance. The accessibility is the product of
// the screen-space one (ssao.blurred, when it ran) and the materials' baked
// one (gbuffer.occlusion), as lighting.ambient_occlusion selects.
#include "gbuffer_read.glsl"
#include "../params/lighting.h"

layout(location = 0) uniform vec3 uAmbient;
layout(location = 1) uniform vec3 uBackground;
layout(binding = 9) uniform sampler2D uSky;  // when lightingParams.sky != 0
layout(binding = 11) uniform sampler2D uBakedOcclusion;  // gbuffer.occlusion
// lighting.directional_in_gbuffer: the directional lights the G-buffer pass
// shaded (gbuffer.directional), added here instead of a full-screen pass each.
layout(location = 2) uniform int uGBufferDirectional;
layout(binding = 12) uniform sampler2D uGBufferDirectionalLight;

out vec4 outColor;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    Surface s = readSurface(px);
    if (isFarDepth(s.depth) || s.pixelType == PIXEL_BACKGROUND) {
        outColor = vec4(lightingParams.sky != 0 ? texelFetch(uSky, px, 0).rgb : uBackground, 1.0);
        return;
    }
    float access = lightingParams.occlusion != 0 ? texelFetch(uOcclusion, px, 0).r : 1.0;
    if (lightingParams.bakedOcclusion != 0) access *= texelFetch(uBakedOcclusion, px, 0).r;
    vec3 emitted = texelFetch(uEmissive, px, 0).rgb;
    vec3 reflectance = s.diffuse + (lightingParams.ambientSpecular != 0 ? s.specular : vec3(0.0));
    vec3 directional = uGBufferDirectional != 0 ? texelFetch(uGBufferDirectionalLight, px, 0).rgb : vec3(0.0);
    outColor = vec4(uAmbient * reflectance * access + emitted + directional, 1.0);
}
