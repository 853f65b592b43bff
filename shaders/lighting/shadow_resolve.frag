#version 450 core
// lighting.shadow = lit / unshadowed luminance of the shadow-mapped lights
// (shadow_sums.frag); 1 where none reaches the pixel and on the sky, as the
// reference's shadow buffer.
#include "../common/bindings.glsl"
layout(binding = SHADOW_SUMS_TEXTURE) uniform sampler2D uSums;
layout(location = 0) out float outShadow;

void main() {
    vec2 s = texelFetch(uSums, ivec2(gl_FragCoord.xy), 0).rg;
    outShadow = s.g > 0.0 ? s.r / s.g : 1.0;
}
