#version 450 core
// The forward lighting strategies (seed 000 section 2, listing 2.6): the
// scene drawn again over the G-buffer depth (GL_EQUAL, no depth writes,
// additive into the L-buffer), each fragment evaluating its material
// (common/material_eval.glsl, what the G-buffer pass encodes, unquantised)
// and shading lights with shade.glsl's lightRadiance, the deferred
// strategies' function.
//   forward: the lights of the draw's CPU-culled list (uFirst, uCount into
//     the index SSBO), summed in 32-bit floats; UNSHADOWED (lights with a
//     shadow map go one at a time through the volume path).
//   FORWARD_ONE_LIGHT (forward_multipass): one light, uLight, shadow lookup included.
#ifndef FORWARD_ONE_LIGHT
#define UNSHADOWED
#endif
#include "../common/bindings.glsl"
#include "shade.glsl"
#include "../common/material_eval.glsl"

layout(location = 1) uniform int uMaterial;
#ifdef FORWARD_ONE_LIGHT
layout(location = 2) uniform int uLight;
#else
layout(location = 2) uniform int uFirst;
layout(location = 3) uniform int uCount;
layout(std430, binding = FORWARD_LIGHTS_SSBO) readonly buffer ForwardLights {
    uint forwardLights[];
};
#endif

in VertexData {
    vec3 viewPosition;
    vec3 normal;
    vec4 tangent;
    vec2 uvs[MATERIAL_SLOTS];
    vec4 color;
} fs;

layout(location = 0) out vec4 outColor;
#ifdef COUNT_OVERLAP
layout(location = 1) out float outOverlap;  // lights evaluated here, added up by the blend
#endif

void main() {
    MaterialSample ms;
    if (!evaluateMaterial(materials[uMaterial], fs.normal, fs.tangent, fs.uvs, fs.color, gl_FrontFacing, ms)) discard;
    // The G-buffer's ranges (geometry.frag), not its quantisation.
    Surface s;
    s.depth = gl_FragCoord.z;
    s.pixelType = PIXEL_SURFACE;
    s.position = fs.viewPosition;
    s.normal = ms.normal;
    s.diffuse = clamp(ms.diffuse, 0.0, 1.0);
    s.specular = clamp(ms.specular, 0.0, 1.0);
    s.exponent = clamp(ms.exponent, 1.0, 2048.0);
    vec3 c = vec3(0.0);
#ifdef FORWARD_ONE_LIGHT
    c = lightRadiance(shadingLight(uLight), s);
    float n = 1.0;
#else
    for (int i = 0; i < uCount; ++i) c += lightRadiance(shadingLight(int(forwardLights[uFirst + i])), s);
    float n = float(uCount);
#endif
    outColor = vec4(c, 0.0);
#ifdef COUNT_OVERLAP
    outOverlap = n;
#endif
}
