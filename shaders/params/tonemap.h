// dw::TonemapPass's parameters (shaders/tonemap/tonemap.frag); see
// prelude.h. `toneOperator` and `bloomComposite` are the choices of
// tonemap.operator and bloom.composite, compared with TONEMAP_OPERATOR_* and
// BLOOM_COMPOSITE_* (KnobRegistry::choiceDefines).
#ifndef DW_PARAMS_TONEMAP_H
#define DW_PARAMS_TONEMAP_H
#include "prelude.h"

#define DW_TONEMAP_PARAMS(FIELD, ARRAY)                                                     \
    FIELD(int, toneOperator)     /* tonemap.operator */                                     \
    FIELD(int, autoWhite)        /* tonemap.auto_white: L_white = the image's maximum */    \
    FIELD(int, srgbOutput)       /* tonemap.srgb */                                         \
    FIELD(int, nanGuard)         /* tonemap.nan_guard */                                    \
    FIELD(int, bloom)            /* bloom.result ran and is composited */                   \
    FIELD(int, bloomComposite)   /* bloom.composite */                                      \
    FIELD(int, autoExposure)     /* tonemap.auto_exposure (other operators than Reinhard) */ \
    FIELD(int, pad0)                                                                        \
    FIELD(float, key)            /* Reinhard's key value a */                               \
    FIELD(float, white)          /* manual L_white */                                       \
    FIELD(float, exposure)       /* EV */                                                   \
    FIELD(float, bloomIntensity) /* bloom.intensity */
DW_PARAM_BLOCK(TonemapParams, tonemap, DW_TONEMAP_PARAMS)
DW_PARAM_SIZE(TonemapParams, 48)

#endif
