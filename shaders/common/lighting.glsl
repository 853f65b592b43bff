// Light table and the shading equation: Blinn-Phong (seed 000, eqs. 2.1-2.3)
// with the attenuation 1/(c + l d + q d^2) (eq. 2.2, seed 001 eq. 1), the
// spot factor (cos theta)^e inside the cutoff (seed 001, section 3.3) or, for
// spot lights from glTF, KHR_lights_punctual's cone (1 inside the inner cone,
// the square of a linear ramp in cos theta between the cones, 0 at the outer
// one), and Ferko's windowed attenuation (seed 000, eq. 3.5) as an option.
#include "bindings.glsl"
// The row (struct Light) and the kinds (LIGHT_DIRECTIONAL, LIGHT_POINT,
// LIGHT_SPOT, LIGHT_SPOT_CONE; a kind >= LIGHT_SPOT is a spot light),
// declared once for C++ and GLSL.
#include "../params/light.h"

layout(std430, binding = LIGHT_SSBO) readonly buffer LightTable {
    Light lights[];
};

// Distance attenuation; 0 outside the light's radius (the in-volume test of
// seed 000 section 3.2.1, so every lighting strategy shades the same region).
// windowed: Ferko's window 1 - (d/r)^k on top (lighting.attenuation).
// The functions here have one exit and no early return: llvmpipe runs a
// return inside a branch as masks over the rest of the function.
float attenuate(Light light, float d, bool windowed, float windowExponent) {
    float radius = light.positionRadius.w;
    vec3 k = light.attenuation.xyz;
    float att = 1.0 / max(k.x + k.y * d + k.z * d * d, 1e-6);
    if (windowed && radius > 0.0) att *= 1.0 - pow(d / radius, windowExponent);
    return radius > 0.0 && d > radius ? 0.0 : att;
}

bool isSpotLight(Light light) { return int(light.attenuation.w + 0.5) >= LIGHT_SPOT; }

// A spot light's factor at cos(theta) from its axis: 0 outside the cone
// (cos theta < cos cutoff), inside it (cos theta)^exponent, or for
// LIGHT_SPOT_CONE t^2 with t = (cos theta - cos outer) / (cos inner - cos outer)
// clamped to [0, 1] (the CPU's reference::spotFactor).
float spotFactor(Light light, float cosTheta) {
    float cosOuter = light.directionCutoff.w;
    float f = pow(max(cosTheta, 0.0), light.intensityExponent.w);
    if (int(light.attenuation.w + 0.5) == LIGHT_SPOT_CONE) {
        float t = clamp((cosTheta - cosOuter) * light.intensityExponent.w, 0.0, 1.0);
        f = t * t;
    }
    return cosTheta >= cosOuter ? f : 0.0;
}

// A bounded light's attenuation times its spot factor at distance d in unit
// direction L (from the point towards the light).
float boundedLightScale(Light light, vec3 L, float d, bool windowed, float windowExponent) {
    float scale = attenuate(light, d, windowed, windowExponent);
    if (isSpotLight(light)) scale *= spotFactor(light, dot(-L, light.directionCutoff.xyz));
    return scale;
}

// Blinn-Phong radiance towards the eye from a light of the given intensity
// times scale, in unit direction L, seen from unit direction V; 0 where
// scale <= 0 or the surface faces away from the light.
vec3 blinnPhong(vec3 intensity, float scale, vec3 L, vec3 V, vec3 N, vec3 diffuse, vec3 specular, float exponent) {
    float nDotL = dot(N, L);
    vec3 H = normalize(L + V);
    float spec = pow(max(dot(N, H), 0.0), exponent);
    vec3 c = vec3(0.0);
    if (scale > 0.0 && nDotL > 0.0) c = intensity * scale * (diffuse * nDotL + specular * spec);
    return c;
}

// Radiance reflected towards the eye by one light at view-space point P.
vec3 shadeLight(Light light, vec3 P, vec3 N, vec3 diffuse, vec3 specular, float exponent,
                bool windowed, float windowExponent) {
    vec3 L = -light.directionCutoff.xyz;
    float scale = 1.0;
    if (int(light.attenuation.w + 0.5) != LIGHT_DIRECTIONAL) {
        vec3 toLight = light.positionRadius.xyz - P;
        float d = length(toLight);
        // No absolute floor but 0 (at the light itself): 1e-6 made L short of
        // unit length, and a scene 1e-8 across dark, for every light within 1e-6.
        L = toLight / max(d, 1e-30);
        scale = boundedLightScale(light, L, d, windowed, windowExponent);
    }
    return blinnPhong(light.intensityExponent.rgb, scale, L, normalize(-P), N, diffuse, specular, exponent);
}
