#version 450 core
// Ambient Occlusion Volumes: gbuffer.depth at the accessibility buffer's
// size (aov.depth), the depth of the full-resolution pixel each AO pixel
// stands for, so the volumes' depth test and aov_volume.frag see the same
// surface. Depth writes only.
#include "../common/camera.glsl"
#include "../params/aov.h"

layout(binding = 0) uniform sampler2D uDepth;  // gbuffer.depth

void main() {
    vec2 uv = gl_FragCoord.xy / vec2(aov.aoSize);
    ivec2 px = ivec2(uv * camera.viewport.xy);
    gl_FragDepth = texelFetch(uDepth, px, 0).r;
}
