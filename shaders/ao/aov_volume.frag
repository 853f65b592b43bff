#version 450 core
// Ambient Occlusion Volumes (McGuire 2010; seed 000 sections 4.6.4, 5.7):
// the occlusion of one triangle (the volume's, from aov_volume.geom) at the
// G-buffer point this fragment covers, added into aov.occlusion; the
// accessibility is 1 - clamp(sum) (aov_resolve.frag).
//
// Occlusion of triangle T at point P with normal N (R = delta = aov.radius):
//     O = F(T') * w(h / R)^k,
// T' the part of T that P can see (above its tangent plane) within R of P
// (the disc of radius sqrt(R^2 - h^2) about P's foot on T's plane, h the
// distance to the plane), F the form factor from a differential area at P,
// the cosine-weighted fraction of P's hemisphere T' covers,
//     F = (1/pi) Int_{directions through T'} cos(theta) dw,
// in Lambert's closed form for a polygon (by Stokes' theorem, a sum over its
// edges):
//     F = 1/(2 pi) sum_i beta_i (N . unit(q_i x q_{i+1})),
// q_i the vertices relative to P, beta_i the angle between q_i and q_{i+1};
// w (planeWeight) the ray-traced AO's per-ray weight 1 / (1 + (d/R)^2) averaged
// over the directions to T's plane within R, and k = aov.falloff (1: the
// reference's weight, 0: every direction within R counts 1). For a plane
// facing P, or any triangle of it, O is then exactly the ray-traced AO's
// integral (renderer/reference); for other orientations the weight is the
// facing plane's (docs/ao.md gives the error, about 0.03 for a perpendicular wall).
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../common/gbuffer.glsl"
#include "../params/aov.h"

// Count only fragments that pass the depth and stencil tests against aov.depth
// (the stencil keeps the sky's pixels out).
layout(early_fragment_tests) in;

// Units 11 and 12: GpuScene::drawEach binds the materials' textures to 0-3 and 10.
layout(binding = AOV_VOLUME_DEPTH_TEXTURE) uniform sampler2D uDepth;   // gbuffer.depth, full resolution
layout(binding = AOV_VOLUME_NORMAL_TEXTURE) uniform sampler2D uNormal;  // gbuffer.normal
layout(binding = AOV_OVERDRAW_IMAGE, r32ui) uniform coherent uimage2D uOverdraw;  // aov.overdraw

flat in vec3 gA;
flat in vec3 gB;
flat in vec3 gC;
flat in vec3 gN;

out float outOcclusion;

const float PI = 3.14159265358979;

// The nearest point of triangle abc to p (Ericson, Real-Time Collision
// Detection 5.1.5: the Voronoi regions of the vertices, edges and face).
vec3 nearestOnTriangle(vec3 p, vec3 a, vec3 b, vec3 c) {
    vec3 ab = b - a, ac = c - a, ap = p - a;
    float d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    vec3 bp = p - b;
    float d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
    vec3 cp = p - c;
    float d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
    float va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    float denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

// Polygons of at most 12 vertices: the triangle (3), cut by the hemisphere
// (4) and by the 8 sides of the disc (one more each).
const int MAX_VERTICES = 12;
const int DISC_SIDES = 8;

// Keeps the part of the convex polygon q[0..count-1] where dot(n, x) >= c
// (Sutherland-Hodgman); returns the new count.
int clipPolygon(inout vec3 q[MAX_VERTICES], int count, vec3 n, float c) {
    vec3 kept[MAX_VERTICES];
    int m = 0;
    for (int i = 0; i < count; ++i) {
        vec3 u = q[i], v = q[i + 1 < count ? i + 1 : 0];
        float hu = dot(n, u) - c, hv = dot(n, v) - c;
        if (hu >= 0.0 && m < MAX_VERTICES) kept[m++] = u;
        if ((hu >= 0.0) != (hv >= 0.0) && m < MAX_VERTICES) kept[m++] = u + (v - u) * (hu / (hu - hv));
    }
    for (int i = 0; i < m; ++i) q[i] = kept[i];
    return m;
}

// Lambert's form factor of the polygon q[0..count-1] (relative to P, above
// its tangent plane) for the normal N.
float polygonFormFactor(vec3 q[MAX_VERTICES], int count, vec3 N) {
    float sum = 0.0;
    for (int i = 0; i < count; ++i) {
        vec3 u = q[i], v = q[i + 1 < count ? i + 1 : 0];
        vec3 c = cross(u, v);
        float s = length(c);
        if (s <= 0.0) continue;  // parallel: the edge subtends no angle
        float beta = atan(s, dot(u, v));
        sum += beta * dot(N, c / s);
    }
    return abs(sum) / (2.0 * PI);
}

// The ray-traced AO's weight 1 / (1 + (d/R)^2), averaged cosine-weighted over
// the directions to a plane at distance h = a R that lie within R (the disc
// below): Int_a^1 2c^3 / (c^2 + a^2) dc / (1 - a^2) with c = cos(theta)
//     = ((1 - a^2) - a^2 ln((1 + a^2) / (2 a^2))) / (1 - a^2),
// 1 at a = 0, 1/2 at a = 1.
float planeWeight(float a) {
    if (a >= 0.999) return 0.5;
    float a2 = a * a;
    if (a2 < 1e-12) return 1.0;
    return ((1.0 - a2) - a2 * log((1.0 + a2) / (2.0 * a2))) / (1.0 - a2);
}

float triangleOcclusion(vec3 P, vec3 N) {
    float delta = aov.radius;
    // Behind the triangle (or in its plane): it cannot occlude P.
    float h = dot(P - gA, gN);
    if (h <= 1e-5 * delta || h >= delta) return 0.0;
    if (length(nearestOnTriangle(P, gA, gB, gC) - P) >= delta) return 0.0;
    vec3 q[MAX_VERTICES];
    q[0] = gA - P;
    q[1] = gB - P;
    q[2] = gC - P;
    // A triangle wholly within delta of P (the small triangles of a
    // tessellated surface, the common case) needs no cut by the disc below.
    float r2 = delta * delta;
    bool withinDelta = dot(q[0], q[0]) <= r2 && dot(q[1], q[1]) <= r2 && dot(q[2], q[2]) <= r2;
    // What P can see: the part above its tangent plane.
    int count = clipPolygon(q, 3, N, 0.0);
    if (count < 3) return 0.0;
    float weight = pow(planeWeight(h / delta), aov.falloff);
    if (withinDelta) return polygonFormFactor(q, count, N) * weight;
    // What lies within delta of P: the disc of radius sqrt(delta^2 - h^2) about
    // P's foot on the plane (at -h gN from P), as the octagon of the same area.
    vec3 t1 = normalize(abs(gN.x) < 0.9 ? cross(gN, vec3(1.0, 0.0, 0.0)) : cross(gN, vec3(0.0, 1.0, 0.0)));
    vec3 t2 = cross(gN, t1);
    float disc = sqrt(delta * delta - h * h) * 1.0548;  // sqrt(pi / (8 sin(pi/8) cos(pi/8)))
    for (int k = 0; k < DISC_SIDES && count >= 3; ++k) {
        float angle = (float(k) + 0.5) * (2.0 * PI / float(DISC_SIDES));
        vec3 m = cos(angle) * t1 + sin(angle) * t2;
        count = clipPolygon(q, count, -m, -disc);
    }
    if (count < 3) return 0.0;
    return polygonFormFactor(q, count, N) * weight;
}

void main() {
    ivec2 aoPixel = ivec2(gl_FragCoord.xy);
    if (aov.countOverdraw != 0 && !gl_HelperInvocation) imageAtomicAdd(uOverdraw, aoPixel, 1u);
    // The full-resolution pixel this AO pixel stands for (as ssao.frag and aov_depth.frag take it).
    vec2 uv = gl_FragCoord.xy / vec2(aov.aoSize);
    ivec2 px = ivec2(uv * camera.viewport.xy);
    float depth = texelFetch(uDepth, px, 0).r;
    if (isFarDepth(depth)) {
        outOcclusion = 0.0;
        return;
    }
    vec3 P = viewPositionAtPixel(px, depth);
    vec3 N = decodeNormalKL(texelFetch(uNormal, px, 0).xy);
    outOcclusion = triangleOcclusion(P, N);
}
