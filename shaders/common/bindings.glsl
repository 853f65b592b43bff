// Binding points; mirrored by dw::binding in renderer/scene/GpuScene.h.
#ifndef BINDINGS_GLSL
#define BINDINGS_GLSL
#define CAMERA_UBO 0
#define MATERIAL_SSBO 1
#define LIGHT_SSBO 2
#define PASS_UBO 3
#define OIT_UBO 4
#endif
