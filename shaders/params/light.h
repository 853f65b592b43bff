// One row of the light table (dw::LightTable, the std430 storage buffer at
// LIGHT_SSBO that every lighting strategy and the shadow pass read through
// shaders/common/lighting.glsl), and the kinds in its attenuation.w; see
// prelude.h. C++: dw::gpu::Light (dw::LightGpu adds the defaults).
#ifndef DW_PARAMS_LIGHT_H
#define DW_PARAMS_LIGHT_H
#include "prelude.h"

DW_PARAM_CONST(int, LIGHT_DIRECTIONAL, 0)
DW_PARAM_CONST(int, LIGHT_POINT, 1)
DW_PARAM_CONST(int, LIGHT_SPOT, 2)       // cutoff and (cos theta)^exponent (seed 001)
DW_PARAM_CONST(int, LIGHT_SPOT_CONE, 3)  // KHR_lights_punctual's inner and outer cone

#define DW_LIGHT_ROW(FIELD, ARRAY)                                                                     \
    FIELD(mat4, volume)            /* unit volume mesh -> world */                                      \
    FIELD(vec4, positionRadius)    /* view-space position, radius (0 = unbounded) */                    \
    FIELD(vec4, directionCutoff)   /* view-space direction it points to, cos(cutoff) (the outer cone) */ \
    FIELD(vec4, intensityExponent) /* rgb intensity; spot exponent, or 1/(cos inner - cos outer) */     \
    FIELD(vec4, attenuation)       /* constant, linear, quadratic, kind (LIGHT_*) */                    \
    FIELD(mat4, shadowMatrix)      /* view space -> the shadow map's space */                           \
    FIELD(vec4, shadowParams)      /* mode (0 none), PCF radius, texel size, layer */                   \
    FIELD(vec4, shadowRange)       /* near, far; constant bias (fixed, per unit distance) */
DW_PARAM_STRUCT(Light, DW_LIGHT_ROW)
DW_PARAM_SIZE(Light, 224)

#endif
