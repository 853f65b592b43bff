#version 450 core
// G-buffer pass: transforms to view space for the fragment shader.
#include "common/camera.glsl"
#include "common/material.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aTangent;
layout(location = 3) in vec2 aUv;
layout(location = 4) in vec4 aColor;  // glTF COLOR_0, white when absent
layout(location = 5) in vec2 aUv1;    // glTF TEXCOORD_1

layout(location = 0) uniform mat4 uModel;
layout(location = 1) uniform int uMaterial;

out VertexData {
    vec3 viewPosition;
    vec3 normal;
    vec4 tangent;
    vec2 uvs[MATERIAL_SLOTS];  // per texture slot (material.glsl's materialUvs)
    vec4 color;
} vs;

void main() {
    mat4 modelView = camera.view * uModel;
    vec4 p = modelView * vec4(aPosition, 1.0);
    mat3 normalMatrix = transpose(inverse(mat3(modelView)));
    vs.viewPosition = p.xyz;
    vs.normal = normalMatrix * aNormal;
    // A mirroring transform (negative determinant) turns cross(N, T) around:
    // flip the bitangent sign so B still follows dP/dv.
    float handedness = determinant(mat3(modelView)) < 0.0 ? -1.0 : 1.0;
    vs.tangent = vec4(mat3(modelView) * aTangent.xyz, aTangent.w * handedness);
    materialUvs(materials[uMaterial], aUv, aUv1, vs.uvs);
    vs.color = aColor;
    gl_Position = camera.projection * p;
}
