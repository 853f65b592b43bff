#version 450 core
// Ambient Occlusion Volumes: gbuffer.depth at the accessibility buffer's
// size (aov.depth), the depth of the full-resolution pixel each AO pixel
// stands for, so the volumes' depth test and aov_volume.frag see the same
// surface, and stencil 1 where there is a surface. Depth and stencil writes only.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../params/aov.h"

layout(binding = AOV_GBUFFER_DEPTH_TEXTURE) uniform sampler2D uDepth;  // gbuffer.depth

void main() {
    vec2 uv = gl_FragCoord.xy / vec2(aov.aoSize);
    ivec2 px = ivec2(uv * camera.viewport.xy);
    float depth = texelFetch(uDepth, px, 0).r;
    // The sky keeps the cleared far depth and stencil 0: no volume shades it.
    if (isFarDepth(depth)) discard;
    gl_FragDepth = depth;
}
