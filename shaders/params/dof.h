// dw::DofPass's parameters (shaders/post/dof.frag); see prelude.h.
#ifndef DW_PARAMS_DOF_H
#define DW_PARAMS_DOF_H
#include "prelude.h"

#define DW_DOF_PARAMS(FIELD, ARRAY)                                                     \
    FIELD(int, nearBlur)        /* dof.near_blur */                                     \
    FIELD(int, farBlur)         /* dof.far_blur */                                      \
    FIELD(int, sampleCount)     /* dof.samples */                                       \
    FIELD(int, cocOnly)         /* write the signed circle of confusion (dof.coc) */    \
    FIELD(float, focusDistance) /* dof.focus_distance, scene units */                   \
    FIELD(float, focusRange)    /* dof.focus_range, scene units */                      \
    FIELD(float, maxRadius)     /* dof.max_radius, pixels */                            \
    FIELD(int, srgbInput)       /* the image is sRGB-encoded (tonemap.srgb) */
DW_PARAM_BLOCK(DofParams, dof, DW_DOF_PARAMS)
DW_PARAM_SIZE(DofParams, 32)

#endif
