#version 450 core
// One shadow-mapped light's share of the shadow factor (lighting.shadow):
// R = luminance of its radiance with the shadow lookup, G = without it, added
// up over the lights by the blend; shadow_resolve.frag divides. The same
// definition as the CPU reference's shadow buffer (ReferenceRenderer.h):
// only lights whose unshadowed radiance is non-zero at the point count.
#include "shade.glsl"
#include "../common/color.glsl"

layout(location = 0) uniform int uLight;
layout(location = 0) out vec2 outSums;

void main() {
    Surface s = readSurface(ivec2(gl_FragCoord.xy));
    vec2 sums = vec2(0.0);
    if (isSurface(s)) {
        Light light = shadingLight(uLight);
        vec3 c = shadeLight(light, s.position, s.normal, s.diffuse, s.specular, s.exponent,
                            lightingParams.windowed != 0, lightingParams.windowExponent);
        if (any(greaterThan(c, vec3(0.0)))) {
            float visibility = 1.0;
            if (light.shadowParams.x > 0.5) {
                bool directional = int(light.attenuation.w + 0.5) == LIGHT_DIRECTIONAL;
                vec3 toLight = directional ? -light.directionCutoff.xyz : light.positionRadius.xyz - s.position;
                float dist = directional ? 0.0 : length(toLight);
                visibility = shadowVisibility(light.shadowMatrix, light.shadowParams, light.shadowRange, s.position,
                                              s.normal, normalize(toLight), dist);
            }
            float y = luminance(c);
            sums = vec2(y * visibility, y);
        }
    }
    outSums = sums;
}
