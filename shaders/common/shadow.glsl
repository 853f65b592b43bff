// Shadow lookups for the lighting pass (seed 000 sections 4.4 and 5.5).
// Depths follow the frame's convention (camera.glsl: reversed or not).
// Bias: the maps are drawn with a slope-scaled polygon offset, and the
// receiver moves a constant number of map texels towards the light.
// 2D maps (directional, spot): the light's clip space reached from the
// camera's view space by B P_L V_L V_C^-1, compared with PCF over
// (2r + 1)^2 hardware-filtered taps. Point lights: a cube map or two
// paraboloids of linear distance, PCF taps in the receiver's tangent plane.
#include "bindings.glsl"
#define SHADOW_NONE 0
#define SHADOW_2D 1
#define SHADOW_CUBE 2
#define SHADOW_PARABOLOID 3

layout(binding = SHADOW_2D_TEXTURE) uniform sampler2DArrayShadow uShadow2D;
layout(binding = SHADOW_CUBE_TEXTURE) uniform samplerCubeArrayShadow uShadowCube;
layout(binding = SHADOW_PARABOLOID_TEXTURE) uniform sampler2DArrayShadow uShadowParaboloid;

// toLight: unit direction from P to the light. range.zw give the constant
// bias as a distance along it (zw: fixed part, part per unit of distance to
// the light), a number of shadow-map texels wide at P. N: P's unit normal
// (view space; zero when unknown).
float shadowVisibility(mat4 shadowMatrix, vec4 params, vec4 range, vec3 P, vec3 N, vec3 toLight, float lightDistance) {
    int mode = int(params.x + 0.5);
    if (mode == SHADOW_NONE) return 1.0;
    P += toLight * (range.z + range.w * lightDistance);
    int radius = int(params.y + 0.5);
    float texel = params.z;
    float layer = params.w;
    float sum = 0.0, taps = 0.0;
    if (mode == SHADOW_2D) {
        vec4 p = shadowMatrix * vec4(P, 1.0);
        p.xyz /= p.w;
        if (any(lessThan(p.xyz, vec3(0.0))) || any(greaterThan(p.xyz, vec3(1.0)))) return 1.0;
        for (int j = -radius; j <= radius; ++j)
            for (int i = -radius; i <= radius; ++i) {
                sum += texture(uShadow2D, vec4(p.xy + vec2(i, j) * texel, layer, p.z));
                taps += 1.0;
            }
        return sum / taps;
    }
    // Point lights (cube or dual paraboloid): the maps store the linear
    // distance from the light (shadow/distance.frag), continuous across cube
    // faces and hemispheres. The PCF taps lie in the receiver's tangent
    // plane, about a map texel apart as seen from the light, and each
    // compares its own distance: a flat receiver never shadows itself,
    // whatever the kernel's width or the face it reaches into (taps spread
    // across the light ray and compared with one distance darkened an open
    // floor with pcf_radius 2-3).
    vec3 v = (shadowMatrix * vec4(P, 1.0)).xyz;  // light frame: a rigid transform of view space
    float len = length(v);
    if (!(len > 0.0)) return 1.0;                // at the light itself
    vec3 nrm = mat3(shadowMatrix) * N;
    if (!(dot(nrm, nrm) > 1e-12)) nrm = -v;      // no normal: taps across the ray
    nrm = normalize(nrm);
    vec3 a = abs(nrm.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0);
    vec3 t = normalize(cross(nrm, a)), b = cross(nrm, t);
    float cosine = max(abs(dot(nrm, v)) / len, 0.25);
    float step = 2.0 * texel * len / cosine;
    float n = range.x, f = range.y;
    for (int j = -radius; j <= radius; ++j)
        for (int i = -radius; i <= radius; ++i) {
            vec3 q = v + (t * float(i) + b * float(j)) * step;
            float ql = length(q);
            // A tap beyond the map's far plane compares as the far plane
            // (lit against a cleared texel): float depth maps do not clamp.
            float ref = clamp((ql - n) / (f - n), 0.0, 1.0);
            if (depthReversed()) ref = 1.0 - ref;
            if (mode == SHADOW_CUBE) {
                sum += texture(uShadowCube, vec4(q, layer), ref);
            } else {
                // Dual paraboloid: front hemisphere is +Z of the light frame.
                vec3 d = q / max(ql, 1e-30);
                float hemisphere = d.z >= 0.0 ? 0.0 : 1.0;
                d.z = abs(d.z);
                vec2 uv = d.xy / (1.0 + d.z) * 0.5 + 0.5;
                sum += texture(uShadowParaboloid, vec4(uv, layer * 2.0 + hemisphere, ref));
            }
            taps += 1.0;
        }
    return sum / taps;
}
