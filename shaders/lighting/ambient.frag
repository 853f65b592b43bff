#version 450 core
// The L-buffer's first write (ambient.glsl's firstRadiance) as a full-screen
// pass, before the lights are blended on top.
#include "ambient.glsl"

out vec4 outColor;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    outColor = vec4(firstRadiance(px, readSurface(px)), 1.0);
}
