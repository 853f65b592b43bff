#version 450 core
// One light's contribution, added to the L-buffer (seed 000 section 5.2.1).
// Shared by every lighting strategy, so their images differ only by rounding.
#include "shade.glsl"

#ifdef VOLUME_ROW
flat in int vLight;  // from volume.vert: one light, or a light of a batch
// Its shading fields, read by volume.vert per vertex: on llvmpipe a flat
// input costs far less than reading the light table at a row that can
// differ between the lanes of a fragment batch (one scalar load per lane and
// field): the batched volumes' lighting pass at 1000 lights, 640x360, took
// 10% (stencil_volumes) and 25% (volumes) less (docs/bench.md).
flat in vec4 vPositionRadius, vDirectionCutoff, vIntensityExponent, vAttenuation;
#else
layout(location = 0) uniform int uLight;
#endif

layout(location = 0) out vec4 outColor;
#ifdef COUNT_OVERLAP
// One per invocation, added up by the blend: the per-pixel cost of the strategy.
layout(location = 1) out float outOverlap;
#endif

void main() {
#ifdef COUNT_OVERLAP
    outOverlap = 1.0;
#endif
    ivec2 px = ivec2(gl_FragCoord.xy);
    Surface s = readSurface(px);
    // Background and cleared depth get 0, not a discard, so the invocation
    // is still counted.
    vec3 c = vec3(0.0);
    if (isSurface(s)) {
#ifdef VOLUME_ROW
        Light light;
        light.volume = mat4(0.0);
        light.positionRadius = vPositionRadius;
        light.directionCutoff = vDirectionCutoff;
        light.intensityExponent = vIntensityExponent;
        light.attenuation = vAttenuation;
        readShadowFields(light, vLight);
#else
        Light light = shadingLight(uLight);
#endif
        c = lightRadiance(light, s);
    }
    outColor = vec4(c, 0.0);
}
