// Shared by the buffer view and its min/max reduction: maps a pixel of the
// view image to the output's texel (grid of layers, cube cross, table; the
// layout is ImageLayout in renderer/inspect/OutputReadback.h, mirrored here), fetches
// it and applies the mapping that precedes range remapping (linear depth,
// decoded normal), so auto-range sees the values the view shows.
//
// One variant per source kind, chosen by BufferView: plain 2D (default),
// SOURCE_MS (multisample), SOURCE_ARRAY (arrays; cubes and cube arrays through
// a 2D-array view of their faces), SOURCE_3D, SOURCE_BUFFER (an SSBO of 4-byte
// words); SOURCE_UINT / SOURCE_INT for integer texture formats.
#include "../common/bindings.glsl"
#include "../common/gbuffer.glsl"

#define MAP_DIRECT 0
#define MAP_LINEAR_DEPTH 1
#define MAP_NORMAL 2
#define MAP_HEATMAP 3
#define MAP_TONEMAP 4
#define MAP_NON_FINITE 5

#define ARRANGE_PLAIN 0
#define ARRANGE_LAYERS 1
#define ARRANGE_CROSSES 2
#define ARRANGE_TABLE 3

layout(std140, binding = PASS_UBO) uniform BufferViewParams {
    ivec4 modes;   // x mapping, y channel (0 rgb, 1 r, 2 g, 3 b, 4 a), z auto range, w mip level
    ivec4 flags;   // x source is KL-encoded normal, y source is depth (1 conventional, 2 reversed; 3 a raw reversed depth map), z source is an sRGB texture, w arrangement
    vec4 range;    // x min, y max, z near, w far
    vec4 extra;    // x exposure (EV) for the tone-mapped view
    ivec4 cell;    // x, y cell (layer, face) size; z first layer (cube) shown; w sample (-1: the mean)
    ivec4 grid;    // x, y view image size; z grid columns; w cells
    ivec4 source;  // x samples; y buffer words per element step; z buffer words are unsigned integers
} view;

#if defined(SOURCE_UINT)
#define SAMPLER_2D usampler2D
#define SAMPLER_MS usampler2DMS
#define SAMPLER_ARRAY usampler2DArray
#define SAMPLER_3D usampler3D
#elif defined(SOURCE_INT)
#define SAMPLER_2D isampler2D
#define SAMPLER_MS isampler2DMS
#define SAMPLER_ARRAY isampler2DArray
#define SAMPLER_3D isampler3D
#else
#define SAMPLER_2D sampler2D
#define SAMPLER_MS sampler2DMS
#define SAMPLER_ARRAY sampler2DArray
#define SAMPLER_3D sampler3D
#endif

// The texel (x, y) of layer z (array layer, 3D slice, cube-map layer), as shaders see it.
#if defined(SOURCE_BUFFER)
layout(std430, binding = 6) readonly buffer SourceWords { uint words[]; };
vec4 fetchRaw(ivec3 s) {
    // Per-pixel buffers: element y * width + x; tables: word x of element y.
    int i = (s.y * view.cell.x + s.x) * view.source.y;
    if (i < 0 || i >= words.length()) return vec4(0.0, 0.0, 0.0, 1.0);
    uint w = words[i];
    return vec4(view.source.z != 0 ? float(w) : uintBitsToFloat(w), 0.0, 0.0, 1.0);
}
#elif defined(SOURCE_MS)
layout(binding = 0) uniform SAMPLER_MS uSource;
vec4 fetchRaw(ivec3 s) {
    if (view.cell.w >= 0) return vec4(texelFetch(uSource, s.xy, view.cell.w));
    vec4 sum = vec4(0.0);
    for (int i = 0; i < view.source.x; ++i) sum += vec4(texelFetch(uSource, s.xy, i));
    return sum / float(max(view.source.x, 1));
}
#elif defined(SOURCE_ARRAY)
layout(binding = 0) uniform SAMPLER_ARRAY uSource;
vec4 fetchRaw(ivec3 s) { return vec4(texelFetch(uSource, s, view.modes.w)); }
#elif defined(SOURCE_3D)
layout(binding = 0) uniform SAMPLER_3D uSource;
vec4 fetchRaw(ivec3 s) { return vec4(texelFetch(uSource, s, view.modes.w)); }
#else
layout(binding = 0) uniform SAMPLER_2D uSource;
vec4 fetchRaw(ivec3 s) { return vec4(texelFetch(uSource, s.xy, view.modes.w)); }
#endif

// Maps a pixel of the view image to the source texel (x, y, layer); false in
// the empty cells of a grid or cross. Mirrors ImageLayout::toSource.
bool viewToSource(ivec2 px, out ivec3 src) {
    src = ivec3(px, 0);
    int arrangement = view.flags.w;
    if (arrangement == ARRANGE_PLAIN) return true;
    if (arrangement == ARRANGE_TABLE) {
        src = ivec3(px.x, view.grid.y - 1 - px.y, 0);  // element 0 in the top row
        return true;
    }
    bool crosses = arrangement == ARRANGE_CROSSES;
    ivec2 cellSize = view.cell.xy * (crosses ? ivec2(4, 3) : ivec2(1, 1));
    ivec2 c = px / cellSize;
    int rows = (view.grid.w + view.grid.z - 1) / view.grid.z;
    int index = (rows - 1 - c.y) * view.grid.z + c.x;  // reading order from the top left
    if (index >= view.grid.w) return false;
    ivec2 local = px - c * cellSize;
    int layer = view.cell.z + index;
    if (!crosses) {
        src = ivec3(local, layer);
        return true;
    }
    // Unfolded cross: +Y on top; -X +Z +X -Z in the middle; -Y below.
    ivec2 f = local / view.cell.xy;
    int face = -1;
    if (f.y == 1) face = f.x == 0 ? 1 : f.x == 1 ? 4 : f.x == 2 ? 0 : 5;
    else if (f.x == 1) face = f.y == 2 ? 2 : 3;
    if (face < 0) return false;
    ivec2 t = local - f * view.cell.xy;
    src = ivec3(t.x, view.cell.y - 1 - t.y, layer * 6 + face);  // row t = 0 at the face's top
    return true;
}

// Window depth in [0, 1] (flags.y: 1 conventional, 2 reversed; dw::DepthConvention) -> distance.
bool depthReversed() { return view.flags.y == 2; }
float linearDepth(float d) {
    float n = view.range.z, f = view.range.w;
    return depthReversed() ? n * f / (n + d * (f - n)) : n * f / (f - d * (f - n));
}

// Applies the pre-range mapping to a fetched value. Returns false for values
// that should not count (background depth, NaN/Inf).
bool mapFetched(inout vec4 v) {
    if (view.flags.y == 3) {
        // Raw window depth (a shadow map) stored reversed: shown the
        // conventional way round, near dark and far white, in either mode.
        v.r = 1.0 - v.r;
    } else if (view.flags.y != 0) {
        if (depthReversed() ? v.r <= 0.0 : v.r >= 1.0) return false;
        if (view.modes.x == MAP_LINEAR_DEPTH) v = vec4(vec3(linearDepth(v.r)), 1.0);
    } else if (view.flags.x != 0) {
        v = vec4(decodeNormalKL(v.xy), 1.0);
    }
    return !any(isnan(v)) && !any(isinf(v));
}

// The mapped value at a pixel of the view image; false where nothing counts
// (empty cells, background depth, NaN/Inf).
bool fetchMapped(ivec2 px, out vec4 v) {
    ivec3 s;
    v = vec4(0.0);
    if (!viewToSource(px, s)) return false;
    v = fetchRaw(s);
    return mapFetched(v);
}

vec4 selectChannel(vec4 v) {
    int c = view.modes.y;
    if (c == 0) return v;
    float s = v[c - 1];
    return vec4(s, s, s, 1.0);
}
