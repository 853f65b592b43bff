// Shadow lookups for the lighting pass (seed 000 sections 4.4 and 5.5).
// Depths follow the frame's convention (camera.glsl: reversed or not).
// Bias: the maps are drawn with a slope-scaled polygon offset, and the
// receiver moves a constant number of map texels towards the light.
// 2D maps (directional, spot): the light's clip space reached from the
// camera's view space by B P_L V_L V_C^-1, compared with PCF over
// (2r + 1)^2 hardware-filtered taps. Point lights: a cube map compared with
// the depth the face's projection gives the offset's major axis, or two
// paraboloids.
#define SHADOW_NONE 0
#define SHADOW_2D 1
#define SHADOW_CUBE 2
#define SHADOW_PARABOLOID 3

layout(binding = 6) uniform sampler2DArrayShadow uShadow2D;
layout(binding = 7) uniform samplerCubeArrayShadow uShadowCube;
layout(binding = 8) uniform sampler2DArrayShadow uShadowParaboloid;

// toLight: unit direction from P to the light. range.zw give the constant
// bias as a distance along it (zw: fixed part, part per unit of distance to
// the light), a number of shadow-map texels wide at P.
float shadowVisibility(mat4 shadowMatrix, vec4 params, vec4 range, vec3 P, vec3 toLight, float lightDistance) {
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
    vec3 v = (shadowMatrix * vec4(P, 1.0)).xyz;
    float n = range.x, f = range.y;
    if (mode == SHADOW_CUBE) {
        float z = max(abs(v.x), max(abs(v.y), abs(v.z)));
        float ref = perspectiveDepth(z, n, f);
        // Offsets across the direction, about one texel apart at this distance.
        vec3 a = abs(v.y) < 0.9 * length(v) ? vec3(0, 1, 0) : vec3(1, 0, 0);
        vec3 t = normalize(cross(v, a)), b = normalize(cross(v, t));
        float step = 2.0 * texel * z;
        for (int j = -radius; j <= radius; ++j)
            for (int i = -radius; i <= radius; ++i) {
                sum += texture(uShadowCube, vec4(v + (t * float(i) + b * float(j)) * step, layer), ref);
                taps += 1.0;
            }
        return sum / taps;
    }
    // Dual paraboloid: front hemisphere is +Z of the light frame.
    float len = length(v);
    vec3 d = v / max(len, 1e-6);
    float hemisphere = d.z >= 0.0 ? 0.0 : 1.0;
    if (d.z < 0.0) d.z = -d.z;
    vec2 uv = d.xy / (1.0 + d.z) * 0.5 + 0.5;
    float ref = (len - n) / (f - n);
    if (depthReversed()) ref = 1.0 - ref;
    for (int j = -radius; j <= radius; ++j)
        for (int i = -radius; i <= radius; ++i) {
            sum += texture(uShadowParaboloid, vec4(uv + vec2(i, j) * texel, layer * 2.0 + hemisphere, ref));
            taps += 1.0;
        }
    return sum / taps;
}
