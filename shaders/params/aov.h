// dw::AovMethod's parameters (shaders/ao/aov_volume.*, aov_depth.frag,
// aov_resolve.frag); see prelude.h.
#ifndef DW_PARAMS_AOV_H
#define DW_PARAMS_AOV_H
#include "prelude.h"

// Flags of the per-draw uniform (location 2 of aov_volume.vert).
DW_PARAM_CONST(int, AOV_DRAW_MIRRORED, 1)      // the model matrix mirrors: its winding is flipped
DW_PARAM_CONST(int, AOV_DRAW_DOUBLE_SIDED, 2)  // a volume on each side of the triangle

#define DW_AOV_PARAMS(FIELD, ARRAY)                                                          \
    FIELD(ivec2, aoSize)        /* the accessibility buffer's size in pixels */              \
    FIELD(float, radius)        /* delta: how far a volume reaches, in world units */        \
    FIELD(float, falloff)       /* exponent k of the falloff (1 - distance / delta)^k */     \
    FIELD(int, insidePass)      /* 0: front faces, 1: back faces (AovMethod::render) */      \
    FIELD(int, countOverdraw)   /* count shaded fragments into aov.overdraw */               \
    FIELD(float, insideMargin)  /* the camera's distance to the near plane's corners */      \
    FIELD(float, pad0)
DW_PARAM_BLOCK(AovParams, aov, DW_AOV_PARAMS)
DW_PARAM_SIZE(AovParams, 32)

#endif
