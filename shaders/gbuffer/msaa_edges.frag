#version 450 core
// MSAA's edge mask (aa.method=msaa; Lauritzen 2010's per-sample edge
// detection): 1 where any sample of the multisampled G-buffer differs from
// sample 0 in coverage (surface against background), in view-space depth by
// more than uRelativeDepth of the nearer one's, in normal by more than the
// angle whose cosine is uNormalCos, or in material (albedo, specular colour
// or exponent by more than 2/255, emission by more than 2%); 0 elsewhere
// (dw::kEdgeRule, renderer/passes/MsaaPass.h).
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/gbuffer.glsl"

layout(binding = MSAA_ALBEDO_TEXTURE) uniform sampler2DMS uAlbedo;
layout(binding = MSAA_NORMAL_TEXTURE) uniform sampler2DMS uNormal;
layout(binding = MSAA_SPECULAR_TEXTURE) uniform sampler2DMS uSpecular;
layout(binding = MSAA_EMISSIVE_TEXTURE) uniform sampler2DMS uEmissive;
layout(binding = MSAA_DEPTH_TEXTURE) uniform sampler2DMS uDepth;

layout(location = 0) uniform int uSamples;
layout(location = 1) uniform float uRelativeDepth;
layout(location = 2) uniform float uNormalCos;

out float outEdge;

const float kMaterialStep = 2.0 / 255.0;

bool differs(ivec2 px, int s, float z0, vec3 n0, vec4 a0, vec4 sp0, vec3 e0) {
    vec4 a = texelFetch(uAlbedo, px, s);
    bool surface0 = a0.a > 0.5 / 255.0, surface = a.a > 0.5 / 255.0;
    if (surface0 != surface) return true;
    if (!surface) return false;  // background in both
    float z = viewPositionAtPixel(px, texelFetch(uDepth, px, s).r).z;
    if (abs(z - z0) > uRelativeDepth * min(abs(z), abs(z0))) return true;
    if (dot(decodeNormal(texelFetch(uNormal, px, s).xy), n0) < uNormalCos) return true;
    vec4 sp = texelFetch(uSpecular, px, s);
    vec3 e = texelFetch(uEmissive, px, s).rgb;
    vec4 da = abs(a - a0), ds = abs(sp - sp0);
    if (max(max(da.r, da.g), da.b) > kMaterialStep || max(max(ds.r, ds.g), max(ds.b, ds.a)) > kMaterialStep) return true;
    vec3 de = abs(e - e0);
    return max(max(de.r, de.g), de.b) > 0.02 * max(max(max(e0.r, e0.g), e0.b), 1e-3);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 a0 = texelFetch(uAlbedo, px, 0);
    float z0 = viewPositionAtPixel(px, texelFetch(uDepth, px, 0).r).z;
    vec3 n0 = decodeNormal(texelFetch(uNormal, px, 0).xy);
    vec4 sp0 = texelFetch(uSpecular, px, 0);
    vec3 e0 = texelFetch(uEmissive, px, 0).rgb;
    float edge = 0.0;
    for (int s = 1; s < uSamples; ++s)
        if (differs(px, s, z0, n0, a0, sp0, e0)) edge = 1.0;
    outEdge = edge;
}
