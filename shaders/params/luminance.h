// dw::LuminancePass's parameters (shaders/tonemap/luminance_reduce.comp);
// see prelude.h. One block for all three variants; each dispatch writes it.
#ifndef DW_PARAMS_LUMINANCE_H
#define DW_PARAMS_LUMINANCE_H
#include "prelude.h"

// The first pass sums LUMINANCE_TILE x LUMINANCE_TILE pixels per work group,
// later passes LUMINANCE_GROUP partial sums (a power of two).
DW_PARAM_CONST(int, LUMINANCE_TILE, 16)
DW_PARAM_CONST(int, LUMINANCE_GROUP, 256)

#define DW_LUMINANCE_PARAMS(FIELD, ARRAY)                                                     \
    FIELD(int, count)           /* partial sums to add up (later passes) */                   \
    FIELD(float, delta)         /* luminance.log_delta: log(delta + L) (first pass) */        \
    FIELD(int, skipBackground)  /* luminance.background = exclude (first pass) */             \
    FIELD(int, footprint)       /* rendered pixels per output pixel per axis (SSAA; first pass) */
DW_PARAM_BLOCK(LuminanceParams, reduction, DW_LUMINANCE_PARAMS)
DW_PARAM_SIZE(LuminanceParams, 16)

#endif
