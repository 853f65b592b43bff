#version 450 core
// Transparent fragments, forward-shaded (seed 003 section 3.4; seed 000
// section 3.5): the material (common/material_eval.glsl, what the G-buffer
// pass evaluates), alpha from the base colour factor and texture, lit by
// every row of the light table with shade.glsl's lightRadiance (and the
// shadow maps when they were all kept: OIT_SHADOWED), plus the ambient term
// and emission; premultiplied by alpha. Fragments behind the opaque surface
// are discarded against gbuffer.depth here, not by the depth test (the
// A-buffer's stencil routing must see only the fragments it stores). Then
// one method stores it:
//   METHOD_LIST: a node of the per-pixel linked list (head image, node SSBO,
//     atomic counter; past oit.nodeBudget lost, counted by the resolve)
//   METHOD_WEIGHTED: McGuire and Bavoil 2013's accumulation and revealage
//   METHOD_ABUFFER: the colour to the stencil-routed sample (the pass sets
//     the stencil state; depth GL_ALWAYS, written)
//   METHOD_PEEL: the nearest fragment behind the previous layer (uPrevDepth)
//   METHOD_DUAL_INIT, METHOD_DUAL: dual depth peeling's depth range and its
//     nearest and farthest layers (Bavoil and Myers 2008)
//   METHOD_FORWARD: blended "over" into the L-buffer, sorted on the CPU
#ifndef OIT_SHADOWED
#define UNSHADOWED
#endif
#include "../common/bindings.glsl"
#include "../lighting/shade.glsl"
#include "../common/material_eval.glsl"
#include "../params/oit.h"

layout(location = 1) uniform int uMaterial;

in VertexData {
    vec3 viewPosition;
    vec3 normal;
    vec4 tangent;
    vec2 uvs[MATERIAL_SLOTS];
    vec4 color;
} fs;

layout(binding = OIT_FRAGMENT_COUNT_IMAGE, r32ui) uniform coherent uimage2D uFragmentCount;  // oit.sample_count
#if defined(METHOD_LIST)
layout(binding = OIT_LIST_HEADS_IMAGE, r32ui) uniform coherent uimage2D uHeads;
// OIT_LIST_NODE_WORDS words a node: premultiplied RGBA (32-bit floats), window depth, next + 1.
layout(std430, binding = OIT_LIST_NODES_SSBO) buffer ListNodes { uint nodeWords[]; };
layout(std430, binding = OIT_LIST_COUNTER_SSBO) buffer ListCounter { uint usedNodes; };
#elif defined(METHOD_WEIGHTED)
layout(location = 0) out vec4 outAccum;
layout(location = 1) out vec4 outRevealage;
#elif defined(METHOD_PEEL)
layout(binding = OIT_PREVIOUS_DEPTH_TEXTURE) uniform sampler2D uPrevDepth;
layout(location = 0) out vec4 outColor;
#elif defined(METHOD_DUAL_INIT)
layout(location = 0) out vec2 outDepth;
#elif defined(METHOD_DUAL)
layout(binding = OIT_PREVIOUS_DEPTH_TEXTURE) uniform sampler2D uPrevDepth;  // (-nearest, farthest) left, as farness
layout(binding = OIT_PEEL_LAYERS_IMAGE, r32ui) uniform coherent uimage2D uLayers;
// This pass's claims: bit 0 the nearest layer taken, bit 1 the farthest.
layout(binding = OIT_DUAL_CLAIMS_IMAGE, r32ui) uniform coherent uimage2D uClaims;
layout(location = 0) out vec2 outDepth;
layout(location = 1) out vec4 outFront;
layout(location = 2) out vec4 outBack;
#else
layout(location = 0) out vec4 outColor;
#endif

bool nearer(float a, float b) { return depthReversed() ? a > b : a < b; }

// McGuire and Bavoil, "Weighted Blended Order-Independent Transparency",
// JCGT 2(2), 2013, equations 7-10: z the view-space distance, d the
// conventional window depth (0 near, 1 far).
float blendWeight(float alpha, float z, float windowDepth) {
    float d = depthReversed() ? 1.0 - windowDepth : windowDepth;
    z = abs(z);
    if (oit.weightFunction == 8) return alpha * clamp(10.0 / (1e-5 + pow(z / 10.0, 3.0) + pow(z / 200.0, 6.0)), 1e-2, 3e3);
    if (oit.weightFunction == 9) return alpha * clamp(0.03 / (1e-5 + pow(z / 200.0, 4.0)), 1e-2, 3e3);
    if (oit.weightFunction == 10) return alpha * max(1e-2, 3e3 * pow(1.0 - d, 3.0));
    return alpha * clamp(10.0 / (1e-5 + pow(z / 5.0, 2.0) + pow(z / 200.0, 6.0)), 1e-2, 3e3);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (!nearer(gl_FragCoord.z, texelFetch(uDepth, px, 0).r)) discard;  // behind the opaque surface
    // Dual depth peeling compares "farness", larger farther in either
    // depth.mode: z, or -z when reversed (-1 near .. 0 far). Not 1 - z: that
    // rounds distinct reversed depths near 0 to one farness, which then
    // counted as equal depths (a loss) on the glass scene's fan.
    float farness = depthReversed() ? -gl_FragCoord.z : gl_FragCoord.z;
#ifdef METHOD_DUAL_INIT
    outDepth = vec2(-farness, farness);  // GL_MAX: (-nearest, farthest)
    if (oit.countFragments != 0 && !gl_HelperInvocation) imageAtomicAdd(uFragmentCount, px, 1u);
    return;
#endif
#ifdef METHOD_DUAL
    vec2 prev = texelFetch(uPrevDepth, px, 0).rg;
    float nearest = -prev.x, farthest = prev.y;
    outDepth = vec2(-2.0);  // below every farness and its negation (both in [-1, 1]): no effect under GL_MAX
    outFront = vec4(0.0);
    outBack = vec4(0.0);
    if (farness < nearest || farness > farthest) discard;  // peeled already
    if (farness > nearest && farness < farthest) {
        outDepth = vec2(-farness, farness);  // still inside: next pass's range
        return;
    }
    // The last pass of an odd oit.peel_layers takes one layer, the nearest:
    // the farthest is left (lost, and counted in oit.overflow).
    if (oit.frontOnly != 0 && farness != nearest) discard;
#endif
#ifdef METHOD_PEEL
    if (!nearer(texelFetch(uPrevDepth, px, 0).r, gl_FragCoord.z)) discard;  // peeled already
#endif
    Material m = materials[uMaterial];
    MaterialSample ms;
    if (!evaluateMaterial(m, fs.normal, fs.tangent, fs.uvs, fs.color, gl_FrontFacing, ms)) discard;
    vec4 base = m.baseColor * fs.color;
    if (m.textures.x != 0) base *= texture(uBaseColorMap, fs.uvs[SLOT_BASE_COLOR]);
    float alpha = clamp(base.a, 0.0, 1.0);

    Surface s;
    s.depth = gl_FragCoord.z;
    s.pixelType = PIXEL_SURFACE;
    s.position = fs.viewPosition;
    s.normal = ms.normal;
    s.diffuse = clamp(ms.diffuse, 0.0, 1.0);
    s.specular = clamp(ms.specular, 0.0, 1.0);
    s.exponent = clamp(ms.exponent, 1.0, 2048.0);
    vec3 reflectance = s.diffuse + (lightingParams.ambientSpecular != 0 ? s.specular : vec3(0.0));
    // Emission clamped as the G-buffer pass clamps it (R11G11B10F's largest
    // value; SceneCheck.h kMaxEmission): opaque and blended surfaces and the
    // CPU reference follow one rule.
    vec3 c = lightingParams.ambient.rgb * reflectance + clamp(ms.emissive, vec3(0.0), vec3(65000.0));
    for (int i = 0; i < oit.lightCount; ++i) c += lightRadiance(shadingLight(i), s);
    vec4 premultiplied = vec4(c * alpha, alpha);

    // Helper invocations (quad neighbours run for derivatives) must not
    // count or store: llvmpipe lets their atomics through, doubling the
    // fragments along every triangle's diagonal.
    if (gl_HelperInvocation) discard;
#ifdef METHOD_ABUFFER
    // Multisample rasterisation: a pixel on the edge two triangles share gets
    // a fragment from each (complementary samples); count the one covering sample 0.
    bool counted = (gl_SampleMaskIn[0] & 1) != 0;
#else
    bool counted = true;
#endif
    if (oit.countFragments != 0 && counted) imageAtomicAdd(uFragmentCount, px, 1u);
#if defined(METHOD_LIST)
    // Past the budget the fragment is lost; the resolve counts it (oit.sample_count - kept).
    uint node = atomicAdd(usedNodes, 1u);
    if (node >= oit.nodeBudget) return;
    uint next = imageAtomicExchange(uHeads, px, node + 1u);  // links are index + 1; 0 ends a list
    uint at = node * uint(OIT_LIST_NODE_WORDS);
    for (int i = 0; i < 4; ++i) nodeWords[at + uint(i)] = floatBitsToUint(premultiplied[i]);
    nodeWords[at + 4u] = floatBitsToUint(gl_FragCoord.z);
    nodeWords[at + 5u] = next;
#elif defined(METHOD_DUAL_INIT)
    // (returned above)
#elif defined(METHOD_DUAL)
    // The nearest or the farthest layer left (the nearest when they are one).
    // A second fragment at exactly that depth would be merged with the first
    // by GL_MAX: it is lost instead, so oit.overflow (fragments - layers)
    // counts it.
    uint side = farness == nearest ? 1u : 2u;
    if ((imageAtomicOr(uClaims, px, side) & side) != 0u) discard;
    imageAtomicAdd(uLayers, px, 1u);
    if (farness == nearest) outFront = premultiplied;
    else outBack = premultiplied;
#elif defined(METHOD_WEIGHTED)
    float w = blendWeight(alpha, fs.viewPosition.z, gl_FragCoord.z);
    outAccum = premultiplied * w;
    outRevealage = vec4(alpha);
#else
    outColor = premultiplied;
#endif
}
