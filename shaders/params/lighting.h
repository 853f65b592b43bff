// dw::LightingPass's parameters, shared by shaders/lighting/ambient.glsl
// (the L-buffer's first write), shaders/lighting/light.frag and any
// strategy's shader; see prelude.h.
// The shaders only ask whether lighting.attenuation is "windowed", so the
// pass looks that choice up by name and sends a flag: the shared lighting
// code needs no defines, and strategies compile their programs without the
// pass's help.
#ifndef DW_PARAMS_LIGHTING_H
#define DW_PARAMS_LIGHTING_H
#include "prelude.h"

#define DW_LIGHTING_PARAMS(FIELD, ARRAY)                                                  \
    FIELD(int, windowed)         /* lighting.attenuation = windowed */                    \
    FIELD(int, occlusion)        /* ao.filtered ran: scale the ambient term by it */      \
    FIELD(int, ambientSpecular)  /* lighting.ambient_specular */                          \
    FIELD(int, sky)              /* the sky pass ran: its texture is the background */    \
    FIELD(float, windowExponent) /* k in the windowed attenuation 1 - (d/r)^k */          \
    FIELD(int, bakedOcclusion)   /* lighting.ambient_occlusion uses gbuffer.occlusion */  \
    FIELD(int, gbufferDirectional) /* add gbuffer.directional (lighting.directional_in_gbuffer) */ \
    FIELD(int, multiBounce)      /* gtao.multibounce with ao.method = gtao: Jimenez et al.'s fit */ \
    FIELD(vec4, ambient)         /* rgb: the scene's ambient intensity i_a */             \
    FIELD(vec4, background)      /* rgb: where no geometry is and the sky did not run */
DW_PARAM_BLOCK(LightingParams, lightingParams, DW_LIGHTING_PARAMS)
DW_PARAM_SIZE(LightingParams, 64)

#endif
