// The frame's camera (dw::CameraUniforms, uploaded by dw::Pipeline at
// CAMERA_UBO), read by every shader that includes shaders/common/camera.glsl;
// see prelude.h. Rendering is camera-relative: `view` is a rotation and world
// positions reach the GPU minus the camera's position (CameraUniforms::origin,
// C++ only).
#ifndef DW_PARAMS_CAMERA_H
#define DW_PARAMS_CAMERA_H
#include "prelude.h"

#define DW_CAMERA_PARAMS(FIELD, ARRAY)                                                        \
    FIELD(mat4, view)                                                                         \
    FIELD(mat4, projection)                                                                   \
    FIELD(mat4, viewProjection)                                                               \
    FIELD(mat4, inverseProjection)                                                            \
    FIELD(mat4, inverseView)                                                                  \
    FIELD(vec4, viewport) /* width, height, 1/width, 1/height */                              \
    FIELD(vec4, clip)     /* near, far, tan(fovY/2), aspect */                                \
    FIELD(vec4, depth)    /* x 1 reversed / 0 conventional, y far depth, z near depth */    \
    FIELD(vec4, gbuffer)  /* x gbuffer.normal_encoding: 0 Kircher-Lawrance, 1 octahedral */
DW_PARAM_BLOCK_AT(CameraBlock, camera, CAMERA_UBO, DW_CAMERA_PARAMS)
DW_PARAM_SIZE(CameraBlock, 384)

#endif
