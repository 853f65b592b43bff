#version 450 core
// Per-channel min and max of the mapped source (auto range of the buffer view).
#include "../common/bindings.glsl"
#include "source.glsl"

struct Range { vec4 lo; vec4 hi; };
layout(std430, binding = BUFFER_VIEW_RANGE_IN_SSBO) readonly buffer RangeIn { Range inData[]; };
layout(std430, binding = BUFFER_VIEW_RANGE_OUT_SSBO) writeonly buffer RangeOut { Range outData[]; };
layout(location = 0) uniform int uCount;

#if defined(FIRST_PASS)
layout(local_size_x = 16, local_size_y = 16) in;
#else
layout(local_size_x = 256) in;
#endif
shared vec4 lo[256];
shared vec4 hi[256];

void main() {
    uint lid = gl_LocalInvocationIndex;
    vec4 a = vec4(3.0e38), b = vec4(-3.0e38);
#if defined(FIRST_PASS)
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = view.viewSize;  // the view image: layers, faces and table cells included
    vec4 v;
    if (px.x < size.x && px.y < size.y && fetchMapped(px, v)) {
        v = selectChannel(v);
        a = v;
        b = v;
    }
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
#else
    uint i = gl_GlobalInvocationID.x;
    if (i < uint(uCount)) {
        a = inData[i].lo;
        b = inData[i].hi;
    }
    uint group = gl_WorkGroupID.x;
#endif
    lo[lid] = a;
    hi[lid] = b;
    barrier();
    for (uint s = 128u; s > 0u; s >>= 1u) {
        if (lid < s) {
            lo[lid] = min(lo[lid], lo[lid + s]);
            hi[lid] = max(hi[lid], hi[lid + s]);
        }
        barrier();
    }
    if (lid == 0u) outData[group] = Range(lo[0], hi[0]);
}
