// dw::BufferView's parameters (shaders/bufferview/view.frag and minmax.comp,
// through source.glsl); see prelude.h. The buffer view is no pass: its
// settings come from the inspector and `render --buffer`, not from knobs, so
// the numbers both sides agree on are DW_PARAM_CONSTs here, and BufferView.cpp
// static_asserts its C++ enums (BufferViewSettings::Mapping, ::Channel,
// ImageLayout::Arrangement) against them.
#ifndef DW_PARAMS_BUFFERVIEW_H
#define DW_PARAMS_BUFFERVIEW_H
#include "prelude.h"

// How a value becomes a colour (BufferViewSettings::Mapping, resolved).
DW_PARAM_CONST(int, VIEW_MAP_DIRECT, 0)        // range-mapped channels
DW_PARAM_CONST(int, VIEW_MAP_LINEAR_DEPTH, 1)  // window depth -> distance, then range-mapped
DW_PARAM_CONST(int, VIEW_MAP_NORMAL, 2)        // [-1, 1] vector as a colour
DW_PARAM_CONST(int, VIEW_MAP_HEATMAP, 3)       // first channel through the turbo colour map
DW_PARAM_CONST(int, VIEW_MAP_TONEMAP, 4)       // HDR colour at an exposure
DW_PARAM_CONST(int, VIEW_MAP_NON_FINITE, 5)    // NaN / +Inf / -Inf highlighted

// Which channel is shown (BufferViewSettings::Channel): all three colours, or one as grey.
DW_PARAM_CONST(int, VIEW_CHANNEL_RGB, 0)
DW_PARAM_CONST(int, VIEW_CHANNEL_R, 1)
DW_PARAM_CONST(int, VIEW_CHANNEL_G, 2)
DW_PARAM_CONST(int, VIEW_CHANNEL_B, 3)
DW_PARAM_CONST(int, VIEW_CHANNEL_A, 4)

// What the source's first channel is as depth (dw::DepthConvention).
DW_PARAM_CONST(int, VIEW_DEPTH_NONE, 0)          // not depth
DW_PARAM_CONST(int, VIEW_DEPTH_CONVENTIONAL, 1)  // a frame's depth, near 0, far 1
DW_PARAM_CONST(int, VIEW_DEPTH_REVERSED, 2)      // a frame's depth, near 1, far 0
DW_PARAM_CONST(int, VIEW_DEPTH_RAW_REVERSED, 3)  // a shadow map stored reversed, shown near dark

// How the view image is laid out (ImageLayout::Arrangement, OutputReadback.h).
DW_PARAM_CONST(int, VIEW_ARRANGE_PLAIN, 0)    // the texture (2D, multisample, per-pixel buffer)
DW_PARAM_CONST(int, VIEW_ARRANGE_LAYERS, 1)   // a grid of layers (arrays, 3D)
DW_PARAM_CONST(int, VIEW_ARRANGE_CROSSES, 2)  // a grid of unfolded cube crosses
DW_PARAM_CONST(int, VIEW_ARRANGE_TABLE, 3)    // a buffer's words, element 0 in the top row

#define DW_BUFFERVIEW_PARAMS(FIELD, ARRAY)                                                         \
    FIELD(int, mapping)       /* VIEW_MAP_* */                                                     \
    FIELD(int, channel)       /* VIEW_CHANNEL_* */                                                 \
    FIELD(int, autoRange)     /* the range is the view's min/max (AutoRange), not rangeMin/Max */  \
    FIELD(int, mipLevel)      /* of the source texture */                                          \
    FIELD(int, klNormal)      /* the source is gbuffer.normal (decoded as camera.gbuffer says) */                \
    FIELD(int, depthKind)     /* VIEW_DEPTH_* */                                                   \
    FIELD(int, srgb)          /* the source is an sRGB texture: linear values shown encoded */     \
    FIELD(int, arrangement)   /* VIEW_ARRANGE_* */                                                 \
    FIELD(float, rangeMin)    /* the manual range */                                               \
    FIELD(float, rangeMax)                                                                         \
    FIELD(float, nearPlane)   /* of the frame's camera, for linear depth */                        \
    FIELD(float, farPlane)                                                                         \
    FIELD(float, exposure)    /* EV, VIEW_MAP_TONEMAP */                                           \
    FIELD(int, firstLayer)    /* the first layer (cube) shown */                                   \
    FIELD(ivec2, cellSize)    /* one layer or face, texels; table: words x elements */             \
    FIELD(ivec2, viewSize)    /* the view image, pixels */                                         \
    FIELD(int, gridColumns)   /* cells a row */                                                    \
    FIELD(int, cells)         /* cells shown */                                                    \
    FIELD(int, sampleIndex)   /* multisample: the sample shown, -1 the mean */                     \
    FIELD(int, samples)       /* multisample: samples a texel */                                   \
    FIELD(int, wordsPerStep)  /* buffer: words from one element to the next */                     \
    FIELD(int, unsignedWords) /* buffer: the words are unsigned integers, not floats */
DW_PARAM_BLOCK(BufferViewParams, view, DW_BUFFERVIEW_PARAMS)
DW_PARAM_SIZE(BufferViewParams, 96)

#endif
