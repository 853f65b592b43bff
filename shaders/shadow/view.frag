#version 450 core
// A shadow map as a flat image for inspection: a 2D layer, a cube map's six
// faces (+X -X +Y / -Y +Z -Z in a 3 x 2 grid) or the two paraboloids side by side.
layout(binding = 0) uniform sampler2DArray uMap2D;
layout(binding = 1) uniform samplerCubeArray uMapCube;
layout(location = 0) uniform ivec2 uModeLayer;  // x: 1 2D, 2 cube, 3 paraboloid; y: slot
layout(location = 1) uniform vec2 uSize;
in vec2 vUv;
out float outDepth;

vec3 cubeDirection(int face, vec2 st) {
    vec2 c = st * 2.0 - 1.0;
    if (face == 0) return vec3(1.0, -c.y, -c.x);
    if (face == 1) return vec3(-1.0, -c.y, c.x);
    if (face == 2) return vec3(c.x, 1.0, c.y);
    if (face == 3) return vec3(c.x, -1.0, -c.y);
    if (face == 4) return vec3(c.x, -c.y, 1.0);
    return vec3(-c.x, -c.y, -1.0);
}

void main() {
    vec2 uv = vec2(vUv.x, 1.0 - vUv.y);
    if (uModeLayer.x == 2) {
        vec2 cell = uv * vec2(3.0, 2.0);
        int face = int(cell.x) + 3 * int(cell.y);
        outDepth = texture(uMapCube, vec4(cubeDirection(face, fract(cell)), float(uModeLayer.y))).r;
    } else if (uModeLayer.x == 3) {
        int half_ = uv.x < 0.5 ? 0 : 1;
        outDepth = texture(uMap2D, vec3(fract(vUv.x * 2.0), vUv.y, float(uModeLayer.y * 2 + half_))).r;
    } else {
        outDepth = texture(uMap2D, vec3(vUv, float(uModeLayer.y))).r;
    }
}
