#version 450 core
// Ambient Occlusion Volumes: accessibility = 1 - clamp(summed occlusion)
// (seed 000 4.6.4: the volumes' occlusion subtracted from 1), into ao.raw.
#include "../common/bindings.glsl"
layout(binding = AOV_OCCLUSION_TEXTURE) uniform sampler2D uOcclusion;  // aov.occlusion
out float outAccessibility;
void main() {
    outAccessibility = 1.0 - clamp(texelFetch(uOcclusion, ivec2(gl_FragCoord.xy), 0).r, 0.0, 1.0);
}
