// dw::DofPass's parameters (shaders/post/dof.frag); see prelude.h.
#ifndef DW_PARAMS_DOF_H
#define DW_PARAMS_DOF_H
#include "prelude.h"

// What a draw writes: dof.result, dof.coc or dof.near_alpha.
DW_PARAM_CONST(int, DOF_WRITE_RESULT, 0)
DW_PARAM_CONST(int, DOF_WRITE_COC, 1)
DW_PARAM_CONST(int, DOF_WRITE_NEAR_ALPHA, 2)

#define DW_DOF_PARAMS(FIELD, ARRAY)                                                     \
    FIELD(int, nearBlur)        /* dof.near_blur */                                     \
    FIELD(int, farBlur)         /* dof.far_blur */                                      \
    FIELD(int, sampleCount)     /* dof.samples */                                       \
    FIELD(int, outputKind)      /* DOF_WRITE_*: which output a draw writes */           \
    FIELD(float, focusDistance) /* dof.focus_distance, scene units */                   \
    FIELD(float, focusRange)    /* dof.focus_range, scene units */                      \
    FIELD(float, maxRadius)     /* dof.max_radius, pixels */                            \
    FIELD(int, srgbInput)       /* the image is sRGB-encoded (tonemap.srgb) */
DW_PARAM_BLOCK(DofParams, dof, DW_DOF_PARAMS)
DW_PARAM_SIZE(DofParams, 32)

#endif
