// dw::SsaaPass's parameters (shaders/post/ssaa_resolve.frag); see prelude.h.
#ifndef DW_PARAMS_SSAA_H
#define DW_PARAMS_SSAA_H
#include "prelude.h"

#define DW_SSAA_PARAMS(FIELD, ARRAY)                                                          \
    FIELD(int, factor)      /* rendered pixels per output pixel along each axis (1, 2, 4) */  \
    FIELD(int, srgbInput)   /* 1: the source holds sRGB-encoded values (averaged linear) */   \
    FIELD(int, pad0)                                                                          \
    FIELD(int, pad1)
DW_PARAM_BLOCK(SsaaParams, ssaa, DW_SSAA_PARAMS)
DW_PARAM_SIZE(SsaaParams, 16)

#endif
