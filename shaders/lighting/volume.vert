#version 450 core
// A light's volume mesh (unit sphere or cone) placed by the light's transform
// (uLight >= 0), or a batch of many lights' meshes placed on the CPU into one
// vertex buffer, each vertex carrying its light-table row (uLight < 0): one
// draw call for many lights, and none of the per-instance work a CPU
// rasteriser does for instanced draws (LightShading::uploadVolumeBatch).
#include "../common/camera.glsl"
#include "../common/lighting.glsl"

layout(location = 0) in vec3 aPosition;  // unit mesh, or camera-relative world when batched
layout(location = 1) in float aRow;      // batched: the vertex's light-table row (exact below 2^24)
layout(location = 0) uniform int uLight;

flat out int vLight;  // the row, for light.frag
// The row's shading fields, for light.frag (see there why here).
flat out vec4 vPositionRadius, vDirectionCutoff, vIntensityExponent, vAttenuation;

void main() {
    if (uLight >= 0) {
        vLight = uLight;
        gl_Position = camera.viewProjection * lights[uLight].volume * vec4(aPosition, 1.0);
    } else {
        vLight = int(aRow + 0.5);
        gl_Position = camera.viewProjection * vec4(aPosition, 1.0);
    }
    vPositionRadius = lights[vLight].positionRadius;
    vDirectionCutoff = lights[vLight].directionCutoff;
    vIntensityExponent = lights[vLight].intensityExponent;
    vAttenuation = lights[vLight].attenuation;
}
