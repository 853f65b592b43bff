#version 450 core
// Ambient Occlusion Volumes (McGuire 2010; seed 000 sections 4.6.4, 5.7):
// a pass-through vertex stage. The geometry stage (aov_volume.geom) builds
// each triangle's occlusion volume from the camera-relative world positions.
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModel;
layout(location = 1) uniform int uMaterial;   // set by GpuScene::drawEach; unused
layout(location = 2) uniform int uDrawFlags;  // AOV_DRAW_* (shaders/params/aov.h)
flat out int vFlags;
void main() {
    vFlags = uDrawFlags + 0 * uMaterial;
    gl_Position = uModel * vec4(aPosition, 1.0);
}
