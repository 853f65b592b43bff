// dw::GtaoMethod's parameters (shaders/ao/gtao.frag); see prelude.h.
#ifndef DW_PARAMS_GTAO_H
#define DW_PARAMS_GTAO_H
#include "prelude.h"

// The most slices and steps per side: gtao.slices's and gtao.steps's
// maxima, and the most probes measuring a thin occluder's width
// (gtao.thin_occluders). At all three, one pixel runs at most
// 16 x (1 + 2 x 32 x (1 + 16)) = 17424 loop iterations, below Mesa's CPU
// budget of 65535 per invocation (renderer/gl/ShaderLoopLimit.h).
DW_PARAM_CONST(int, GTAO_MAX_SLICES, 16)
DW_PARAM_CONST(int, GTAO_MAX_STEPS, 32)
DW_PARAM_CONST(int, GTAO_MAX_WIDTH_PROBES, 16)

#define DW_GTAO_PARAMS(FIELD, ARRAY)                                                         \
    FIELD(ivec2, aoSize)       /* the AO target's size in pixels */                          \
    FIELD(int, shift)          /* log2(frame size / AO size): 0 full, 1 half */              \
    FIELD(int, slices)         /* gtao.slices */                                             \
    FIELD(int, steps)          /* gtao.steps, per side of each slice */                      \
    FIELD(float, radius)       /* world (view-space) radius */                               \
    FIELD(float, falloff)      /* gtao.falloff: share of the radius over which a sample fades */ \
    FIELD(float, thickness)    /* gtao.thickness: blend toward a lower horizon sample */     \
    FIELD(float, thinOccluders) /* gtao.thin_occluders: 0 thin occluders as thick, 1 only their angle */ \
    FIELD(float, pixelScale)   /* view-space length 1 at depth 1 in full-resolution pixels */ \
    FIELD(float, minPixels)    /* the first step's least distance, in full-resolution pixels */ \
    FIELD(float, denoisePlane) /* edge-aware denoise: plane distance (x depth) of weight 1/e */ \
    FIELD(int, bentNormals)    /* gtao.bent_normals: write gtao.bent_normal (colour attachment 1) */ \
    FIELD(float, pad0)                                                                      \
    FIELD(float, pad1)                                                                      \
    FIELD(float, pad2)
DW_PARAM_BLOCK(GtaoParams, gtao, DW_GTAO_PARAMS)
DW_PARAM_SIZE(GtaoParams, 64)

#endif
