// dw::AoFilterPass's parameters, shared by shaders/ssao/blur.frag and
// shaders/ssao/upsample.frag; see prelude.h. `mode` is ssao_blur.mode's
// choice, compared with SSAO_BLUR_MODE_* (KnobRegistry::choiceDefines).
#ifndef DW_PARAMS_SSAO_BLUR_H
#define DW_PARAMS_SSAO_BLUR_H
#include "prelude.h"

#define DW_SSAO_BLUR_PARAMS(FIELD, ARRAY)                                                 \
    FIELD(int, mode)         /* ssao_blur.mode */                                         \
    FIELD(int, radius)       /* taps each side, in AO pixels (blur) */                    \
    FIELD(ivec2, aoSize)     /* the AO buffer's size */                                   \
    FIELD(ivec2, direction)  /* (1, 0) or (0, 1) (blur) */                                \
    FIELD(float, delta)      /* delta in 1 / (delta + |depth difference|), scene units */ \
    FIELD(float, sigma)      /* the gaussian's standard deviation in AO pixels (blur) */
DW_PARAM_BLOCK(SsaoBlurParams, blur, DW_SSAO_BLUR_PARAMS)
DW_PARAM_SIZE(SsaoBlurParams, 32)

#endif
