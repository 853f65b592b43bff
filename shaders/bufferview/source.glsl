// Shared by the buffer view and its min/max reduction: fetches a named output's
// texel and applies the mapping that precedes range remapping (linear depth,
// decoded normal), so auto-range sees the values the view shows.
#include "../common/bindings.glsl"
#include "../common/gbuffer.glsl"

#define MAP_DIRECT 0
#define MAP_LINEAR_DEPTH 1
#define MAP_NORMAL 2
#define MAP_HEATMAP 3
#define MAP_TONEMAP 4

layout(std140, binding = PASS_UBO) uniform BufferViewParams {
    ivec4 modes;   // x mapping, y channel (0 rgb, 1 r, 2 g, 3 b, 4 a), z auto range, w mip level
    ivec4 flags;   // x source is KL-encoded normal, y source is depth, z source is an sRGB texture
    vec4 range;    // x min, y max, z near, w far
    vec4 extra;    // x exposure (EV) for the tone-mapped view
} view;

layout(binding = 0) uniform sampler2D uSource;

float linearDepth(float d) {
    float n = view.range.z, f = view.range.w;
    float z = d * 2.0 - 1.0;
    return 2.0 * n * f / (f + n - z * (f - n));
}

// Returns false for texels that should not count (background depth, NaN/Inf).
bool fetchMapped(ivec2 px, out vec4 v) {
    v = texelFetch(uSource, px, view.modes.w);
    if (view.flags.y != 0) {
        if (v.r >= 1.0) return false;
        if (view.modes.x == MAP_LINEAR_DEPTH) v = vec4(vec3(linearDepth(v.r)), 1.0);
    } else if (view.flags.x != 0) {
        v = vec4(decodeNormalKL(v.xy), 1.0);
    }
    return !any(isnan(v)) && !any(isinf(v));
}

vec4 selectChannel(vec4 v) {
    int c = view.modes.y;
    if (c == 0) return v;
    float s = v[c - 1];
    return vec4(s, s, s, 1.0);
}
