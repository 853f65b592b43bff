#version 450 core
// Forward preview modes (the CMSC 23700 viewer's wireframe and texture modes).
#include "../common/camera.glsl"
#include "../common/material.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in vec2 aUv;
layout(location = 4) in vec4 aColor;
layout(location = 5) in vec2 aUv1;
layout(location = 0) uniform mat4 uModel;
layout(location = 1) uniform int uMaterial;

out vec3 vNormal;
out vec3 vViewPos;
out vec2 vUv;  // the base colour texture's coordinates (UV set and transform applied)
out vec4 vColor;

void main() {
    mat4 modelView = camera.view * uModel;
    vec4 p = modelView * vec4(aPosition, 1.0);
    vNormal = transpose(inverse(mat3(modelView))) * aNormal;
    vViewPos = p.xyz;
    vec2 uvs[MATERIAL_SLOTS];
    materialUvs(materials[uMaterial], aUv, aUv1, uvs);
    vUv = uvs[SLOT_BASE_COLOR];
    vColor = aColor;
    gl_Position = camera.projection * p;
}
