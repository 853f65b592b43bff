#version 450 core
// MSAA (aa.method=msaa): sample uSample of the multisampled G-buffer into the
// ordinary G-buffer, whose formats it shares, where aa.edges is 1 (the others
// keep the cleared background: pixel type 0, far depth), so every lighting
// strategy shades that sample on edge pixels alone.
// Albedo and specular are sRGB (or UNORM16) in both: fetched linear here and
// encoded again on write (GL_FRAMEBUFFER_SRGB), which gives back the stored code.
#include "../common/bindings.glsl"

layout(binding = MSAA_ALBEDO_TEXTURE) uniform sampler2DMS uAlbedo;
layout(binding = MSAA_NORMAL_TEXTURE) uniform sampler2DMS uNormal;
layout(binding = MSAA_SPECULAR_TEXTURE) uniform sampler2DMS uSpecular;
layout(binding = MSAA_EMISSIVE_TEXTURE) uniform sampler2DMS uEmissive;
layout(binding = MSAA_OCCLUSION_TEXTURE) uniform sampler2DMS uOcclusion;
layout(binding = MSAA_DEPTH_TEXTURE) uniform sampler2DMS uDepth;
layout(binding = MSAA_EDGES_TEXTURE) uniform sampler2D uEdges;
#ifdef DIRECTIONAL_IN_GBUFFER
layout(binding = MSAA_DIRECTIONAL_TEXTURE) uniform sampler2DMS uDirectional;
layout(location = 5) out vec4 outDirectional;
#endif

layout(location = 0) uniform int uSample;

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec2 outNormal;
layout(location = 2) out vec4 outSpecular;
layout(location = 3) out vec4 outEmissive;
layout(location = 4) out float outOcclusion;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (texelFetch(uEdges, px, 0).r < 0.5) discard;
    outAlbedo = texelFetch(uAlbedo, px, uSample);
    outNormal = texelFetch(uNormal, px, uSample).xy;
    outSpecular = texelFetch(uSpecular, px, uSample);
    outEmissive = texelFetch(uEmissive, px, uSample);
    outOcclusion = texelFetch(uOcclusion, px, uSample).r;
#ifdef DIRECTIONAL_IN_GBUFFER
    outDirectional = texelFetch(uDirectional, px, uSample);
#endif
    gl_FragDepth = texelFetch(uDepth, px, uSample).r;
}
