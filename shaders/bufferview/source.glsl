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

// The parameter block `view` and the VIEW_* values are declared once, for
// BufferView.cpp too, in shaders/params/bufferview.h.
#include "../params/bufferview.h"

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
layout(std430, binding = BUFFER_VIEW_SOURCE_SSBO) readonly buffer SourceWords { uint words[]; };
vec4 fetchRaw(ivec3 s) {
    // Per-pixel buffers: element y * width + x; tables: word x of element y.
    int i = (s.y * view.cellSize.x + s.x) * view.wordsPerStep;
    if (i < 0 || i >= words.length()) return vec4(0.0, 0.0, 0.0, 1.0);
    uint w = words[i];
    return vec4(view.unsignedWords != 0 ? float(w) : uintBitsToFloat(w), 0.0, 0.0, 1.0);
}
#elif defined(SOURCE_MS)
layout(binding = BUFFER_VIEW_SOURCE_TEXTURE) uniform SAMPLER_MS uSource;
vec4 fetchRaw(ivec3 s) {
    if (view.sampleIndex >= 0) return vec4(texelFetch(uSource, s.xy, view.sampleIndex));
    vec4 sum = vec4(0.0);
    for (int i = 0; i < view.samples; ++i) sum += vec4(texelFetch(uSource, s.xy, i));
    return sum / float(max(view.samples, 1));
}
#elif defined(SOURCE_ARRAY)
layout(binding = BUFFER_VIEW_SOURCE_TEXTURE) uniform SAMPLER_ARRAY uSource;
vec4 fetchRaw(ivec3 s) { return vec4(texelFetch(uSource, s, view.mipLevel)); }
#elif defined(SOURCE_3D)
layout(binding = BUFFER_VIEW_SOURCE_TEXTURE) uniform SAMPLER_3D uSource;
vec4 fetchRaw(ivec3 s) { return vec4(texelFetch(uSource, s, view.mipLevel)); }
#else
layout(binding = BUFFER_VIEW_SOURCE_TEXTURE) uniform SAMPLER_2D uSource;
vec4 fetchRaw(ivec3 s) { return vec4(texelFetch(uSource, s.xy, view.mipLevel)); }
#endif

// Maps a pixel of the view image to the source texel (x, y, layer); false in
// the empty cells of a grid or cross. Mirrors ImageLayout::toSource.
bool viewToSource(ivec2 px, out ivec3 src) {
    src = ivec3(px, 0);
    int arrangement = view.arrangement;
    if (arrangement == VIEW_ARRANGE_PLAIN) return true;
    if (arrangement == VIEW_ARRANGE_TABLE) {
        src = ivec3(px.x, view.viewSize.y - 1 - px.y, 0);  // element 0 in the top row
        return true;
    }
    bool crosses = arrangement == VIEW_ARRANGE_CROSSES;
    ivec2 cellSize = view.cellSize * (crosses ? ivec2(4, 3) : ivec2(1, 1));
    ivec2 c = px / cellSize;
    int rows = (view.cells + view.gridColumns - 1) / view.gridColumns;
    int index = (rows - 1 - c.y) * view.gridColumns + c.x;  // reading order from the top left
    if (index >= view.cells) return false;
    ivec2 local = px - c * cellSize;
    int layer = view.firstLayer + index;
    if (!crosses) {
        src = ivec3(local, layer);
        return true;
    }
    // Unfolded cross: +Y on top; -X +Z +X -Z in the middle; -Y below.
    ivec2 f = local / view.cellSize;
    int face = -1;
    if (f.y == 1) face = f.x == 0 ? 1 : f.x == 1 ? 4 : f.x == 2 ? 0 : 5;
    else if (f.x == 1) face = f.y == 2 ? 2 : 3;
    if (face < 0) return false;
    ivec2 t = local - f * view.cellSize;
    src = ivec3(t.x, view.cellSize.y - 1 - t.y, layer * 6 + face);  // row t = 0 at the face's top
    return true;
}

// Window depth in [0, 1] (depthKind: conventional or reversed; dw::DepthConvention) -> distance.
bool depthReversed() { return view.depthKind == VIEW_DEPTH_REVERSED; }
float linearDepth(float d) {
    float n = view.nearPlane, f = view.farPlane;
    return depthReversed() ? n * f / (n + d * (f - n)) : n * f / (f - d * (f - n));
}

// Applies the pre-range mapping to a fetched value. Returns false for values
// that should not count (background depth, NaN/Inf).
bool mapFetched(inout vec4 v) {
    if (view.depthKind == VIEW_DEPTH_RAW_REVERSED) {
        // Raw window depth (a shadow map) stored reversed: shown the
        // conventional way round, near dark and far white, in either mode.
        v.r = 1.0 - v.r;
    } else if (view.depthKind != VIEW_DEPTH_NONE) {
        if (depthReversed() ? v.r <= 0.0 : v.r >= 1.0) return false;
        if (view.mapping == VIEW_MAP_LINEAR_DEPTH) v = vec4(vec3(linearDepth(v.r)), 1.0);
    } else if (view.klNormal != 0) {
        v = vec4(decodeNormal(v.xy), 1.0);
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
    int c = view.channel;
    if (c == VIEW_CHANNEL_RGB) return v;
    // VIEW_CHANNEL_R .. VIEW_CHANNEL_A are 1 .. 4.
    float s = v[c - 1];
    return vec4(s, s, s, 1.0);
}
