// dw::SsaoMethod's parameters (shaders/ssao/ssao.frag); see prelude.h.
#ifndef DW_PARAMS_SSAO_H
#define DW_PARAMS_SSAO_H
#include "prelude.h"

// The most kernel points a pixel takes: ssao.samples's maximum and the size
// of the kernel array.
DW_PARAM_CONST(int, SSAO_MAX_SAMPLES, 64)
// The random rotation vectors tile the screen in SSAO_NOISE_SIZE^2 blocks (a power of two).
DW_PARAM_CONST(int, SSAO_NOISE_SIZE, 4)

#define DW_SSAO_PARAMS(FIELD, ARRAY)                                           \
    FIELD(int, sampleCount)   /* kernel points used (ssao.samples) */          \
    FIELD(int, rangeCheck)    /* ssao.range_check */                           \
    FIELD(ivec2, aoSize)      /* the AO target's size in pixels */             \
    FIELD(float, radius)      /* sampling radius in scene units */             \
    FIELD(float, intensity)   /* AO = 1 - intensity x mean occlusion */        \
    FIELD(float, bias)        /* depth tolerance, a fraction of the radius */  \
    FIELD(float, pad0)                                                         \
    ARRAY(vec4, kernel, SSAO_MAX_SAMPLES) /* points in the unit ball, xyz */
DW_PARAM_BLOCK(SsaoParams, ssao, DW_SSAO_PARAMS)
DW_PARAM_SIZE(SsaoParams, 1056)

#endif
