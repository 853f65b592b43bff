#version 450 core
// Shadow map: scene depth from the light (directional: orthographic, spot and
// cube faces: perspective).
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModel;
layout(location = 2) uniform mat4 uLightViewProjection;
layout(location = 3) uniform vec3 uLightPosition;  // point lights (shadow/distance.frag)
out vec3 vLightOffset;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vLightOffset = world.xyz - uLightPosition;
    gl_Position = uLightViewProjection * world;
}
