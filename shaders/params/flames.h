// dw::FlamesPass's parameters (shaders/flames/flame.vert, flame.frag); see prelude.h.
#ifndef DW_PARAMS_FLAMES_H
#define DW_PARAMS_FLAMES_H
#include "prelude.h"

// Particles drawn per batch (one upload of this block, one draw); a fire of
// more particles takes several batches. 2 x 16 bytes a particle keeps the
// block under GL's 16 KiB minimum of GL_MAX_UNIFORM_BLOCK_SIZE.
DW_PARAM_CONST(int, FLAMES_BATCH, 256)

#define DW_FLAMES_PARAMS(FIELD, ARRAY)                                                         \
    FIELD(int, count)        /* particles in this batch */                                   \
    FIELD(float, softness)   /* soft-particle fade distance in front of a surface, scene units */ \
    FIELD(float, pad0)                                                                        \
    FIELD(float, pad1)                                                                        \
    ARRAY(vec4, centre, FLAMES_BATCH)   /* xyz camera-relative world position, w half width */ \
    ARRAY(vec4, emission, FLAMES_BATCH) /* rgb radiance at the sprite's centre, w half height */
DW_PARAM_BLOCK(FlamesParams, flames, DW_FLAMES_PARAMS)
DW_PARAM_SIZE(FlamesParams, 8208)

#endif
