#version 450 core
// A light's volume mesh (unit sphere or cone) placed by the light's transform.
#include "../common/camera.glsl"
#include "../common/lighting.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform int uLight;

void main() {
    gl_Position = camera.viewProjection * lights[uLight].volume * vec4(aPosition, 1.0);
}
