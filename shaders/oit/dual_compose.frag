#version 450 core
// Dual depth peeling (Bavoil and Myers 2008; seed 000 section 3.5.1): adds
// the pass's nearest layer under the front layers so far (attachment 0,
// blended GL_DST_ALPHA, GL_ONE / GL_ZERO, GL_ONE_MINUS_SRC_ALPHA: C += T c,
// T *= 1 - a) and its farthest layer over the back layers so far
// (attachment 1, GL_ONE, GL_ONE_MINUS_SRC_ALPHA / GL_ZERO,
// GL_ONE_MINUS_SRC_ALPHA: C = c + (1 - a) C, T *= 1 - a).
#include "../common/bindings.glsl"
layout(binding = OIT_FRONT_LAYER_TEXTURE) uniform sampler2D uFrontLayer;
layout(binding = OIT_BACK_LAYER_TEXTURE) uniform sampler2D uBackLayer;

layout(location = 0) out vec4 outFront;
layout(location = 1) out vec4 outBack;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    outFront = texelFetch(uFrontLayer, px, 0);
    outBack = texelFetch(uBackLayer, px, 0);
}
