// dw::BloomPass's parameters, shared by every shader in shaders/bloom/ (each
// draw of the pass fills what its shader reads); see prelude.h.
#ifndef DW_PARAMS_BLOOM_H
#define DW_PARAMS_BLOOM_H
#include "prelude.h"

#define DW_BLOOM_PARAMS(FIELD, ARRAY)                                                         \
    FIELD(int, nanGuard)       /* tonemap.nan_guard: drop NaN and infinity from the input */  \
    FIELD(int, levels)         /* levels blurred (0: the image is too small for any) */       \
    FIELD(float, threshold)    /* bright: a multiple of the log-average luminance */          \
    FIELD(float, pad0)                                                                        \
    FIELD(vec2, sourceTexel)   /* down, up: one texel of the level read (up: the coarser) */  \
    FIELD(vec2, targetTexel)   /* mipsum, down, up: one texel of the target */
DW_PARAM_BLOCK(BloomParams, bloom, DW_BLOOM_PARAMS)
DW_PARAM_SIZE(BloomParams, 32)

#endif
