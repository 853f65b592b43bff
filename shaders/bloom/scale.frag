#version 450 core
// Divides the summed levels by their count, so both bloom methods give an average.
#include "../common/bindings.glsl"
layout(binding = 0) uniform sampler2D uSource;
layout(std140, binding = PASS_UBO) uniform BloomParams {
    ivec4 modes;   // y levels
    vec4 values;
} bloom;
out vec4 outColor;
void main() { outColor = vec4(texelFetch(uSource, ivec2(gl_FragCoord.xy), 0).rgb / float(bloom.modes.y + 1), 1.0); }
