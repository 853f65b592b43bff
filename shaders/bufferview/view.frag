#version 450 core
// Maps any named output to a displayable RGBA8 image: channel selection,
// manual or automatic range, linear depth, normals as colours, a heat map for
// counts, and a simple tone map for HDR buffers. Layered, multisample and
// buffer sources are laid out by source.glsl (grid, cross, table).
#include "../common/bindings.glsl"
#include "source.glsl"
#include "../common/color.glsl"

struct Range { vec4 lo; vec4 hi; };
layout(std430, binding = BUFFER_VIEW_AUTO_RANGE_SSBO) readonly buffer AutoRange { Range autoRange[]; };

out vec4 outColor;

#include "turbo.h"

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    ivec3 src;
    if (!viewToSource(px, src)) {
        // The empty cells of a grid of layers or of a cube cross.
        outColor = vec4(0.03, 0.03, 0.035, 1.0);
        return;
    }
    vec4 raw = fetchRaw(src);
    if (view.mapping == VIEW_MAP_NON_FINITE) {
        // Non-finite values highlighted over a dim picture of the rest.
        bool positiveInf = false, negativeInf = false;
        for (int i = 0; i < 4; ++i)
            if (isinf(raw[i])) {
                positiveInf = positiveInf || raw[i] > 0.0;
                negativeInf = negativeInf || raw[i] < 0.0;
            }
        if (any(isnan(raw))) outColor = vec4(1.0, 0.0, 1.0, 1.0);
        else if (positiveInf) outColor = vec4(1.0, 0.0, 0.0, 1.0);
        else if (negativeInf) outColor = vec4(0.0, 0.3, 1.0, 1.0);
        else {
            float x = max(dot(abs(raw.rgb), vec3(0.2126, 0.7152, 0.0722)), 0.0);
            outColor = vec4(vec3(0.35 * x / (1.0 + x)), 1.0);
        }
        return;
    }
    vec4 v = raw;
    if (!mapFetched(v)) {
        // Background depth and non-finite values: a dark checker, not a colour.
        bool odd = ((px.x / 8 + px.y / 8) & 1) == 1;
        outColor = vec4(vec3(odd ? 0.10 : 0.16), 1.0);
        if (any(isnan(raw))) outColor = vec4(1.0, 0.0, 1.0, 1.0);
        return;
    }
    v = selectChannel(v);
    int mapping = view.mapping;
    vec4 lo = vec4(view.rangeMin), hi = vec4(view.rangeMax);
    if (view.autoRange != 0) {
        lo = autoRange[0].lo;
        hi = autoRange[0].hi;
        if (view.channel == VIEW_CHANNEL_RGB && mapping != VIEW_MAP_HEATMAP) {
            // One range for all colour channels keeps hues honest.
            float l = min(min(lo.r, lo.g), lo.b), h = max(max(hi.r, hi.g), hi.b);
            lo = vec4(l);
            hi = vec4(h);
        }
        if (mapping == VIEW_MAP_HEATMAP) lo = vec4(min(lo.r, 0.0));
        // A constant buffer (a range of no width: gbuffer.occlusion without
        // an occlusion texture is all 1) shows its value against [0, 1], not black.
        bvec4 noWidth = lessThanEqual(hi - lo, 1e-6 * max(abs(hi), vec4(1.0)));
        lo = mix(lo, min(lo, vec4(0.0)), noWidth);
        hi = mix(hi, max(hi, vec4(1.0)), noWidth);
    }
    vec4 span = max(hi - lo, vec4(1e-20));
    vec3 c;
    if (mapping == VIEW_MAP_NORMAL) {
        c = view.channel == VIEW_CHANNEL_RGB ? v.xyz * 0.5 + 0.5 : vec3(v.x * 0.5 + 0.5);
    } else if (mapping == VIEW_MAP_HEATMAP) {
        c = turbo((v.r - lo.r) / span.r);
    } else if (mapping == VIEW_MAP_TONEMAP) {
        vec3 x = max(v.rgb, 0.0) * exp2(view.exposure);
        c = linearToSrgb(x / (1.0 + x));
    } else {
        c = clamp((v.rgb - lo.rgb) / span.rgb, 0.0, 1.0);
        // Linear colour stored in sRGB textures (albedo, specular) displays encoded.
        if (view.srgb != 0 && view.channel == VIEW_CHANNEL_RGB) c = linearToSrgb(c);
    }
    outColor = vec4(c, 1.0);
}
