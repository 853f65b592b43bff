// One bounded or directional light's radiance at a G-buffer surface: the
// shading equation (common/lighting.glsl) times the light's shadow lookup when
// it has a map. Every lighting strategy evaluates this one function, the
// fragment shader once per light (light.frag) and the tiled and clustered
// shaders in a loop over their light lists, so their images agree to rounding.
// A shader that never shades a light with a shadow map (the tiled and
// clustered grids, the batched light volumes) defines UNSHADOWED first: the shadow lookup is then left
// out, which on llvmpipe more than halves the loop's cost although the branch
// would never be taken.
#include "gbuffer_read.glsl"
#include "../params/lighting.h"
#include "../common/lighting.glsl"
#include "../common/shadow.glsl"

// The shadow map's fields of light-table row `row` into `light`, when the
// light has a map; none under UNSHADOWED.
void readShadowFields(inout Light light, int row) {
    light.shadowParams = vec4(0.0);
    light.shadowMatrix = mat4(0.0);
    light.shadowRange = vec4(0.0);
#ifndef UNSHADOWED
    light.shadowParams = lights[row].shadowParams;
    if (light.shadowParams.x > 0.5) {
        light.shadowMatrix = lights[row].shadowMatrix;
        light.shadowRange = lights[row].shadowRange;
    }
#endif
}

// Light-table row `row` with only the fields lightRadiance reads (on
// llvmpipe, reading all 30 vec4 of a row where only 4 are needed is
// measurable in a shader run per pixel).
Light shadingLight(int row) {
    Light light;
    light.volume = mat4(0.0);
    light.positionRadius = lights[row].positionRadius;
    light.directionCutoff = lights[row].directionCutoff;
    light.intensityExponent = lights[row].intensityExponent;
    light.attenuation = lights[row].attenuation;
    readShadowFields(light, row);
    return light;
}

vec3 lightRadiance(Light light, Surface s) {
    vec3 c = shadeLight(light, s.position, s.normal, s.diffuse, s.specular, s.exponent,
                        lightingParams.windowed != 0, lightingParams.windowExponent);
#ifndef UNSHADOWED
    if (light.shadowParams.x > 0.5 && any(greaterThan(c, vec3(0.0)))) {
        bool directional = int(light.attenuation.w + 0.5) == LIGHT_DIRECTIONAL;
        vec3 toLight = directional ? -light.directionCutoff.xyz : light.positionRadius.xyz - s.position;
        float dist = directional ? 0.0 : length(toLight);
        c *= shadowVisibility(light.shadowMatrix, light.shadowParams, light.shadowRange, s.position, s.normal,
                              normalize(toLight), dist);
    }
#endif
    return c;
}

#ifdef UNSHADOWED
// lightRadiance of a bounded light for a caller that has already computed,
// as shadeLight does, toLight = position - P, d = length(toLight),
// L = toLight / max(d, 1e-30) and V = normalize(-P) (the grid strategies
// compute d for their radius test and V once per pixel): the same
// operations, so the same value.
vec3 lightRadianceAt(Light light, Surface s, vec3 L, float d, vec3 V) {
    return blinnPhong(light.intensityExponent.rgb,
                      boundedLightScale(light, L, d, lightingParams.windowed != 0, lightingParams.windowExponent), L,
                      V, s.normal, s.diffuse, s.specular, s.exponent);
}

// Whether a light whose radius test passed (d <= radius, or the light
// unbounded: the test attenuate() makes) reaches the point: for a spot
// light, inside its cone (shadeLight's test, the same operations, so both
// agree at the edge). The grid strategies test the radius on the light's
// first texel and then this before shading, so the lights of a tile's or
// cluster's list that cannot reach a pixel cost a distance, not a shading.
bool spotReaches(Light light, vec3 L) {
    return !isSpotLight(light) || dot(-L, light.directionCutoff.xyz) >= light.directionCutoff.w;
}
#endif

// Whether the pixel holds a surface to light (not background, not cleared depth).
bool isSurface(Surface s) { return !(isFarDepth(s.depth) || s.pixelType == PIXEL_BACKGROUND); }
