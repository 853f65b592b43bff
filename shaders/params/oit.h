// dw::OitPass's parameters (renderer/passes/OitPass.h), shared by
// shaders/oit/transparent.frag and shaders/oit/resolve.frag; see prelude.h.
// At OIT_UBO, because the transparent surfaces are lit with the lighting
// pass's block (LightingParams) at PASS_UBO.
#ifndef DW_PARAMS_OIT_H
#define DW_PARAMS_OIT_H
#include "prelude.h"

// The A-buffer's largest sample count the resolve reads (a GPU offers 8 to
// 32 for RGBA16F; llvmpipe 4).
DW_PARAM_CONST(int, OIT_MAX_SAMPLES, 32)
// The linked list's resolve sorts at most this many fragments per pixel in
// a local array; further ones are dropped and counted in oit.overflow.
DW_PARAM_CONST(int, OIT_LIST_MAX_FRAGMENTS, 32)
// 32-bit words per linked-list node: premultiplied RGBA as four 32-bit
// floats (halves overflowed at 65504), window depth, next node + 1.
DW_PARAM_CONST(int, OIT_LIST_NODE_WORDS, 6)

#define DW_OIT_PARAMS(FIELD, ARRAY)                                                          \
    FIELD(int, samples)        /* A-buffer: samples per pixel; peeling: layers */           \
    FIELD(uint, nodeBudget)    /* linked list: nodes in the node buffer */                  \
    FIELD(int, weightFunction) /* weighted: 7, 8, 9 or 10 (McGuire and Bavoil's equation) */\
    FIELD(int, countFragments) /* add every fragment that reaches the pixel to oit.sample_count */ \
    FIELD(int, lightCount)     /* rows of the light table */                                \
    FIELD(int, peelLayer)      /* depth peeling: the layer being peeled (0: the nearest) */ \
    FIELD(int, frontOnly)      /* dual peeling: keep the nearest layer only (odd layers' last pass) */ \
    FIELD(uint, walkLimit)     /* linked list: nodes one pixel's walk reads at most (the driver's loop budget); 0: all */
DW_PARAM_BLOCK_AT(OitParams, oit, OIT_UBO, DW_OIT_PARAMS)
DW_PARAM_SIZE(OitParams, 32)

#endif
