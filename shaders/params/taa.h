// dw::TaaPass's parameters (shaders/post/taa.frag); see prelude.h.
#ifndef DW_PARAMS_TAA_H
#define DW_PARAMS_TAA_H
#include "prelude.h"

#define DW_TAA_PARAMS(FIELD, ARRAY)                                                                        \
    FIELD(mat4, reprojection)    /* this frame's NDC (x, y, window depth) -> last frame's clip, unjittered */ \
    FIELD(float, blend)          /* aa.taa_blend: the current frame's weight */                           \
    FIELD(float, rejectDistance) /* aa.taa_reject: a clamp that moves the history further rejects it */   \
    FIELD(int, historyValid)     /* 0: no history (first frame, a resize, a new scene) */                 \
    FIELD(int, pad0)
DW_PARAM_BLOCK(TaaParams, taa, DW_TAA_PARAMS)
DW_PARAM_SIZE(TaaParams, 80)

#endif
