#version 450 core
// Decoded G-buffer views, computed only when something asks for them:
// the view-space normal (KL-decoded) and the view-space position
// reconstructed from depth. Background pixels are (0, 0, 0, 0); surfaces have w = 1.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/gbuffer.glsl"

layout(binding = GBUFFER_DECODE_NORMAL_TEXTURE) uniform sampler2D uNormal;
layout(binding = GBUFFER_DECODE_DEPTH_TEXTURE) uniform sampler2D uDepth;

layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec4 outPosition;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(uDepth, px, 0).r;
    if (isFarDepth(depth)) {
        outNormal = vec4(0.0);
        outPosition = vec4(0.0);
        return;
    }
    outNormal = vec4(decodeNormal(texelFetch(uNormal, px, 0).xy), 1.0);
    outPosition = vec4(viewPositionAtPixel(px, depth), 1.0);
}
