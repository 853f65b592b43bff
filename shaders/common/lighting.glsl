// Light table and the shading equation: Blinn-Phong (seed 000, eqs. 2.1-2.3)
// with the attenuation 1/(c + l d + q d^2) (eq. 2.2, seed 001 eq. 1), the
// spot factor (cos theta)^e inside the cutoff (seed 001, section 3.3), and
// Ferko's windowed attenuation (seed 000, eq. 3.5) as an option.
#include "bindings.glsl"

#define LIGHT_DIRECTIONAL 0
#define LIGHT_POINT 1
#define LIGHT_SPOT 2

struct Light {
    mat4 volume;            // unit volume mesh -> world
    vec4 positionRadius;    // view-space position, radius (0 = unbounded)
    vec4 directionCutoff;   // view-space direction the light points to, cos(cutoff)
    vec4 intensityExponent; // rgb intensity, spot exponent
    vec4 attenuation;       // constant, linear, quadratic, type
    mat4 shadowMatrix;      // view space -> the shadow map's space
    vec4 shadowParams;      // mode, PCF radius, texel size, layer
    vec4 shadowRange;       // near, far (cube and paraboloid maps)
};

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

// A bounded light's attenuation times its spot factor at distance d in unit
// direction L (from the point towards the light).
float boundedLightScale(Light light, vec3 L, float d, bool windowed, float windowExponent) {
    float scale = attenuate(light, d, windowed, windowExponent);
    if (int(light.attenuation.w + 0.5) == LIGHT_SPOT) {
        float cosTheta = dot(-L, light.directionCutoff.xyz);
        scale *= cosTheta >= light.directionCutoff.w ? pow(max(cosTheta, 0.0), light.intensityExponent.w) : 0.0;
    }
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
