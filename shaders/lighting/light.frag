#version 450 core
// One light's contribution, added to the L-buffer (seed 000 section 5.2.1).
// Shared by every lighting strategy, so their images differ only by rounding.
#include "shade.glsl"

#ifdef VOLUME_ROW
flat in int vLight;  // from volume.vert: one light, or an instance of a batch
#define LIGHT_ROW vLight
#else
layout(location = 0) uniform int uLight;
#define LIGHT_ROW uLight
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
    if (isFarDepth(s.depth) || s.pixelType == PIXEL_BACKGROUND) {
        outColor = vec4(0.0);  // not discarded, so the invocation is still counted
        return;
    }
    vec3 c = lightRadiance(lights[LIGHT_ROW], s);
    outColor = vec4(c, 0.0);
}
