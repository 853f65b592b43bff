#version 450 core
// Textured mode: the base colour (texture x factor) under a headlight, no
// deferred lighting. Wireframe mode: the base colour, brightened, on lines.
#include "../common/bindings.glsl"
#include "../common/material.glsl"
#include "../common/color.glsl"

layout(location = 1) uniform int uMaterial;
layout(location = 2) uniform int uWireframe;
layout(binding = MATERIAL_BASE_COLOR_TEXTURE) uniform sampler2D uBaseColorMap;

in vec3 vNormal;
in vec3 vViewPos;
in vec2 vUv;
in vec4 vColor;
out vec4 outColor;

void main() {
    Material m = materials[uMaterial];
    vec4 base = m.baseColor * vColor;
    if (m.textures.x != 0) base *= texture(uBaseColorMap, vUv);
    if (m.flags.y == ALPHA_MASK && base.a < m.params.w) discard;
    if (uWireframe != 0) {
        outColor = vec4(linearToSrgb(0.35 + 0.65 * base.rgb), 1.0);
        return;
    }
    vec3 N = normalize(vNormal);
    if (!gl_FrontFacing) N = -N;
    float headlight = max(dot(N, normalize(-vViewPos)), 0.0);
    outColor = vec4(linearToSrgb(base.rgb * (0.25 + 0.75 * headlight)), 1.0);
}
