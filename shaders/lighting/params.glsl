#include "../common/bindings.glsl"
// dw::LightingPass parameters (std140).
layout(std140, binding = PASS_UBO) uniform LightingParams {
    ivec4 modes;   // x attenuation mode, y use occlusion, z ambient includes specular, w sky texture
    vec4 values;   // x window exponent
} lightingParams;
