#version 450 core
// Wireframes and markers over the viewport image.
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModelViewProjection;
void main() { gl_Position = uModelViewProjection * vec4(aPosition, 1.0); }
