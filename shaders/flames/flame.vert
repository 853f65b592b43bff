#version 450 core
// One flame particle a quad (6 vertices, no vertex buffer), facing the camera:
// a billboard in view space, its half width and half height from the block
// (short and fat at birth, tall and thin at the end of a life, seed 004).
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../params/flames.h"

out vec2 vCorner;        // -1..1 across the quad
out vec3 vView;          // view-space position
flat out vec3 vEmission; // radiance at the centre

void main() {
    const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    int particle = gl_VertexID / 6;
    vec2 c = corners[gl_VertexID % 6];
    vec4 centre = flames.centre[particle];
    vec4 emission = flames.emission[particle];
    vec3 view = (camera.view * vec4(centre.xyz, 1.0)).xyz;
    // The quad's up is the world's up seen from the camera, so flames stay upright when the camera rolls or looks down.
    vec3 up = normalize(mat3(camera.view) * vec3(0.0, 1.0, 0.0));
    vec3 right = normalize(cross(up, vec3(0.0, 0.0, 1.0)));
    if (dot(right, right) < 1e-6) right = vec3(1.0, 0.0, 0.0);
    view += right * (c.x * centre.w) + up * (c.y * emission.w);
    vCorner = c;
    vView = view;
    vEmission = emission.rgb;
    gl_Position = camera.projection * vec4(view, 1.0);
}
