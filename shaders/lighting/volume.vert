#version 450 core
// A light's volume mesh (unit sphere or cone) placed by the light's transform.
// One light (uLight >= 0), or instanced: instance i draws light-table row
// volumeRows[uFirst + i] (a batch of lights in one draw call, so the CPU cost
// per light is no longer a draw call and its state changes).
#include "../common/camera.glsl"
#include "../common/lighting.glsl"

// Mirrored by binding::kVolumeRowsSsbo in renderer/lighting/LightingStrategy.h.
#define VOLUME_ROWS_SSBO 8

layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform int uLight;
layout(location = 1) uniform int uFirst;

layout(std430, binding = VOLUME_ROWS_SSBO) readonly buffer VolumeRows {
    uint volumeRows[];
};

flat out int vLight;  // the row, for light.frag

void main() {
    int row = uLight >= 0 ? uLight : int(volumeRows[uFirst + gl_InstanceID]);
    vLight = row;
    gl_Position = camera.viewProjection * lights[row].volume * vec4(aPosition, 1.0);
}
