#version 450 core
// Forward preview modes (the CMSC 23700 viewer's wireframe and texture modes).
#include "../common/camera.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in vec2 aUv;
layout(location = 0) uniform mat4 uModel;

out vec3 vNormal;
out vec3 vViewPos;
out vec2 vUv;

void main() {
    mat4 modelView = camera.view * uModel;
    vec4 p = modelView * vec4(aPosition, 1.0);
    vNormal = transpose(inverse(mat3(modelView))) * aNormal;
    vViewPos = p.xyz;
    vUv = aUv;
    gl_Position = camera.projection * p;
}
