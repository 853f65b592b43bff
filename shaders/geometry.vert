#version 450 core
// G-buffer pass: transforms to view space for the fragment shader.
#include "common/camera.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aTangent;
layout(location = 3) in vec2 aUv;

layout(location = 0) uniform mat4 uModel;

out VertexData {
    vec3 viewPosition;
    vec3 normal;
    vec4 tangent;
    vec2 uv;
} vs;

void main() {
    mat4 modelView = camera.view * uModel;
    vec4 p = modelView * vec4(aPosition, 1.0);
    mat3 normalMatrix = transpose(inverse(mat3(modelView)));
    vs.viewPosition = p.xyz;
    vs.normal = normalMatrix * aNormal;
    vs.tangent = vec4(mat3(modelView) * aTangent.xyz, aTangent.w);
    vs.uv = aUv;
    gl_Position = camera.projection * p;
}
