// dw::FxaaPass's parameters (shaders/post/fxaa.frag); see prelude.h.
#ifndef DW_PARAMS_FXAA_H
#define DW_PARAMS_FXAA_H
#include "prelude.h"

#define DW_FXAA_PARAMS(FIELD, ARRAY)                                                          \
    FIELD(float, edgeThreshold)    /* fxaa.edge_threshold, relative to the brightest luma */  \
    FIELD(float, edgeThresholdMin) /* fxaa.edge_threshold_min, absolute */                    \
    FIELD(float, subpixel)         /* fxaa.subpixel */                                        \
    FIELD(int, searchSteps)        /* steps along the edge each way (fxaa.quality) */
DW_PARAM_BLOCK(FxaaParams, fxaa, DW_FXAA_PARAMS)
DW_PARAM_SIZE(FxaaParams, 16)

#endif
