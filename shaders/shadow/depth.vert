#version 450 core
// Shadow map: scene depth from the light (directional: orthographic, spot and
// cube faces: perspective).
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModel;
layout(location = 2) uniform mat4 uLightViewProjection;
void main() { gl_Position = uLightViewProjection * uModel * vec4(aPosition, 1.0); }
