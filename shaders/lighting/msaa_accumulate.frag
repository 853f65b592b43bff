#version 450 core
// MSAA's box resolve of the shaded radiance (aa.method=msaa): with uFirst the
// sum takes the L-buffer (the pixel centres' shading) where aa.edges is 0 and
// 0 on edge pixels; otherwise a sample's L-buffer is added (additive
// blending) with weight uWeight (1/N) on edge pixels, nothing elsewhere.
#include "../common/bindings.glsl"

layout(binding = MSAA_LBUFFER_TEXTURE) uniform sampler2D uRadiance;
layout(binding = MSAA_EDGES_TEXTURE) uniform sampler2D uEdges;

layout(location = 0) uniform int uFirst;
layout(location = 1) uniform float uWeight;

out vec4 outColor;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    bool edge = texelFetch(uEdges, px, 0).r >= 0.5;
    vec4 c = texelFetch(uRadiance, px, 0);
    if (uFirst != 0) {
        outColor = edge ? vec4(0.0) : c;
        return;
    }
    if (!edge) discard;
    outColor = c * uWeight;
}
