#version 450 core
// Divides the summed levels by their count, so both bloom methods give an average.
#include "../common/bindings.glsl"
#include "../params/bloom.h"
layout(binding = BLOOM_SOURCE_TEXTURE) uniform sampler2D uSource;
out vec4 outColor;
void main() { outColor = vec4(texelFetch(uSource, ivec2(gl_FragCoord.xy), 0).rgb / float(bloom.levels + 1), 1.0); }
