// G-buffer encodings (seed 000, sections 3.1 and 5.2):
//  albedo   RGBA8 sRGB: diffuse colour, alpha = pixel type / 255
//  normal   view-space normal as gbuffer.normal_encoding says: kl16 RG16_SNORM
//           Kircher-Lawrance transform (seed 000); oct16 RG16_SNORM or oct8
//           RG8_SNORM octahedral (Cigolle, Donow, Evangelakos, Mara, McGuire,
//           Meyer, "A Survey of Efficient Representations for Independent Unit
//           Vectors", JCGT 3(2), 2014, section 3.3). The frame's choice is
//           camera.gbuffer.x (0 KL, 1 octahedral): encodeNormal / decodeNormal.
//  specular RGBA8 sRGB: specular colour, alpha = log2(exponent) / 11
//  emissive R11F_G11F_B10F: emitted radiance (glTF emissive materials)
//  depth    DEPTH32F_STENCIL8; position is reconstructed from it.
#ifndef GBUFFER_GLSL
#define GBUFFER_GLSL

#define PIXEL_BACKGROUND 0.0
#define PIXEL_SURFACE 1.0

// n' = (n + (0,0,1)) / |n + (0,0,1)|; store n'.xy (seed 000, eq. 3.1).
vec2 encodeNormalKL(vec3 n) {
    vec3 m = vec3(n.xy, n.z + 1.0);
    float len = length(m);
    // n = (0,0,-1) faces exactly away from the viewer; any unit xy decodes back to it.
    return len > 1e-7 ? m.xy / len : vec2(1.0, 0.0);
}

// z = sqrt(1 - |n'.xy|^2); n = (2 z n'.x, 2 z n'.y, 2 z^2 - 1) (eqs. 3.2, 3.3).
vec3 decodeNormalKL(vec2 e) {
    float z = sqrt(max(1.0 - dot(e, e), 0.0));
    return vec3(2.0 * z * e, 2.0 * z * z - 1.0);
}

// Octahedral: project onto the octahedron |x| + |y| + |z| = 1, fold the
// lower half (z < 0) over the diagonals onto the square [-1, 1]^2.
vec2 octSignNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }
vec2 encodeNormalOct(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    return n.z <= 0.0 ? (1.0 - abs(p.yx)) * octSignNotZero(p) : p;
}
vec3 decodeNormalOct(vec2 e) {
    vec3 v = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (v.z < 0.0) v.xy = (1.0 - abs(v.yx)) * octSignNotZero(v.xy);
    return normalize(v);
}

// The frame's encoding (the camera block's gbuffer.x).
#include "../params/camera.h"
bool gbufferOctahedral() { return camera.gbuffer.x > 0.5; }
vec2 encodeNormal(vec3 n) { return gbufferOctahedral() ? encodeNormalOct(n) : encodeNormalKL(n); }
vec3 decodeNormal(vec2 e) { return gbufferOctahedral() ? decodeNormalOct(e) : decodeNormalKL(e); }

// Blinn-Phong exponents 1..2048 on a log scale in 8 bits.
float encodeExponent(float n) { return clamp(log2(max(n, 1.0)) / 11.0, 0.0, 1.0); }
float decodeExponent(float a) { return exp2(a * 11.0); }

#endif
