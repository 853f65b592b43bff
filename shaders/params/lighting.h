// dw::LightingPass's parameters, shared by shaders/lighting/ambient.frag and
// shaders/lighting/light.frag; see prelude.h. `attenuation` is
// lighting.attenuation's choice, compared with LIGHTING_ATTENUATION_*
// (KnobRegistry::choiceDefines, passed to the light shaders by LightShading).
#ifndef DW_PARAMS_LIGHTING_H
#define DW_PARAMS_LIGHTING_H
#include "prelude.h"

#define DW_LIGHTING_PARAMS(FIELD, ARRAY)                                                  \
    FIELD(int, attenuation)      /* lighting.attenuation */                               \
    FIELD(int, occlusion)        /* ssao.blurred ran: scale the ambient term by it */     \
    FIELD(int, ambientSpecular)  /* lighting.ambient_specular */                          \
    FIELD(int, sky)              /* the sky pass ran: its texture is the background */    \
    FIELD(float, windowExponent) /* k in the windowed attenuation 1 - (d/r)^k */          \
    FIELD(float, pad0)                                                                    \
    FIELD(float, pad1)                                                                    \
    FIELD(float, pad2)
DW_PARAM_BLOCK(LightingParams, lightingParams, DW_LIGHTING_PARAMS)
DW_PARAM_SIZE(LightingParams, 32)

#endif
