// dw::SkyboxPass's parameters (shaders/sky/sky.frag); see prelude.h.
#ifndef DW_PARAMS_SKY_H
#define DW_PARAMS_SKY_H
#include "prelude.h"

// What the shader draws: skybox.mode resolved against the scene (its choice
// "scene" and "environment" become one of these), so these are not a knob's
// choices but the pass's own values, written here once for both languages.
DW_PARAM_CONST(int, SKY_KIND_COLOR, 0)
DW_PARAM_CONST(int, SKY_KIND_PROCEDURAL, 1)
DW_PARAM_CONST(int, SKY_KIND_EQUIRECT, 2)
DW_PARAM_CONST(int, SKY_KIND_CUBE, 3)

#define DW_SKY_PARAMS(FIELD, ARRAY)                                                 \
    FIELD(int, kind)            /* SKY_KIND_* */                                    \
    FIELD(int, hasSun)          /* a directional light draws a sun disc */          \
    FIELD(float, intensity)     /* multiplier on the sky's radiance */              \
    FIELD(float, rotation)      /* of the environment about +Y, radians */          \
    FIELD(vec3, zenith)         /* procedural sky colours */                        \
    FIELD(float, cosSunRadius)  /* cos(half the sun's angular size) */              \
    FIELD(vec3, horizon)                                                            \
    FIELD(float, pad0)                                                              \
    FIELD(vec3, ground)                                                             \
    FIELD(float, pad1)                                                              \
    FIELD(vec3, sunDirection)   /* world direction towards the sun */               \
    FIELD(float, pad2)                                                              \
    FIELD(vec3, sunColor)       /* radiance of the disc */                          \
    FIELD(float, pad3)
DW_PARAM_BLOCK(SkyParams, sky, DW_SKY_PARAMS)
DW_PARAM_SIZE(SkyParams, 96)

#endif
