#version 450 core
// Ambient Occlusion Volumes (McGuire 2010; seed 000 section 4.6.4, figure
// 4.9, and section 5.7): each triangle's occlusion volume is the prism
// between the triangle's plane and that plane moved aov.radius (delta) along
// the triangle's normal, bounded by its three edge planes moved delta
// outwards in the triangle's plane: every point within delta of the triangle,
// on its front side, lies inside. The fragment stage (aov_volume.frag) then
// evaluates the triangle's occlusion at the G-buffer point the volume covers.
//
// Camera inside a volume (seed 000 5.7 draws a full-screen quad there): the
// prism's front faces are clipped away, so such volumes are drawn in a second
// pass as their back faces, with the depth test reversed (the fragment
// passes where the back face lies behind the surface, i.e. the surface is
// in front of the volume's far side). A convex prism gives each pixel at
// most one front face and one back face, so either way each volume shades a
// pixel at most once. "Inside" is taken with a margin: the camera within the
// distance of the near plane's corners of every face plane (then the near
// plane may cut the volume); a volume only near the camera is then drawn by
// its back faces too, which is still right.
#include "../common/camera.glsl"
#include "../params/aov.h"

layout(triangles) in;
// Two volumes (double-sided triangles) of 5 faces: 2 caps x 3 + 3 sides x 4.
layout(triangle_strip, max_vertices = 36) out;

flat in int vFlags[];
// The occluding triangle in view space, its unit normal (the volume's side).
flat out vec3 gA;
flat out vec3 gB;
flat out vec3 gC;
flat out vec3 gN;

vec3 corner[6];  // 0-2 base (in the triangle's plane), 3-5 top

void emitVertex(vec3 p) {
    gl_Position = camera.projection * vec4(p, 1.0);
    EmitVertex();
}

// Emits the face (p0..p3, a triangle when `quad` is false) whose outward
// normal is `outward` if this pass draws it: its front faces in the outside
// pass, its back faces in the inside pass. The order makes it counter-
// clockwise as seen from the camera (clockwise when `mirrored`: GpuScene
// culls with the draw's own front-face winding).
void emitFace(vec3 p0, vec3 p1, vec3 p2, vec3 p3, bool quad, vec3 outward, bool mirrored) {
    bool facesCamera = dot(outward, -p0) > 0.0;
    if (facesCamera != (aov.insidePass == 0)) return;
    // Seen from the camera, an outward face is counter-clockwise when p0, p1,
    // p2 turn around `outward` (right-handed); a back face shows its inside.
    bool ccw = dot(cross(p1 - p0, p2 - p0), outward) > 0.0;
    if (!facesCamera) ccw = !ccw;
    if (mirrored) ccw = !ccw;
    if (quad) {
        // Strip p0 p1 p3 p2 covers the quad p0 p1 p2 p3; reversed: p0 p3 p1 p2.
        if (ccw) { emitVertex(p0); emitVertex(p1); emitVertex(p3); emitVertex(p2); }
        else { emitVertex(p0); emitVertex(p3); emitVertex(p1); emitVertex(p2); }
    } else {
        if (ccw) { emitVertex(p0); emitVertex(p1); emitVertex(p2); }
        else { emitVertex(p0); emitVertex(p2); emitVertex(p1); }
    }
    EndPrimitive();
}

void emitVolume(vec3 a, vec3 b, vec3 c, vec3 n, bool mirrored) {
    float delta = aov.radius;
    vec3 v[3] = vec3[3](a, b, c);
    vec3 middle = (a + b + c) / 3.0;
    // Outward edge normals in the triangle's plane: edge i runs v[i] -> v[i+1].
    vec3 e[3];
    for (int i = 0; i < 3; ++i) {
        vec3 m = normalize(cross(v[(i + 1) % 3] - v[i], n));
        e[i] = dot(m, middle - v[i]) > 0.0 ? -m : m;
    }
    // Corner i: where the edge lines through it, moved delta out, meet
    // (v + delta (e_prev + e_next) / (1 + e_prev . e_next)); a sliver's tip is
    // held to 20 delta.
    for (int i = 0; i < 3; ++i) {
        vec3 ep = e[(i + 2) % 3], en = e[i];
        corner[i] = v[i] + delta * (ep + en) / max(1.0 + dot(ep, en), 0.1);
        corner[i + 3] = corner[i] + delta * n;
    }
    // Frustum culling: a volume whose six corners all lie outside one side
    // plane of the view frustum, or all behind the camera (view z >= 0), is
    // convex and so holds no visible G-buffer point: it would shade nothing.
    // Dropped here it costs no clipping or rasterisation (the near and far
    // planes do not clip with depth clamping on, so without this a volume
    // behind the camera still went through the rasteriser's setup).
    bvec4 allOut = bvec4(true);
    bool allBehind = true;
    for (int i = 0; i < 6; ++i) {
        vec4 clip = camera.projection * vec4(corner[i], 1.0);
        // Each test is a half-space through the eye (linear in the view-space
        // position), so it holds for corners behind the camera too.
        allOut.x = allOut.x && clip.x > clip.w;
        allOut.y = allOut.y && clip.x < -clip.w;
        allOut.z = allOut.z && clip.y > clip.w;
        allOut.w = allOut.w && clip.y < -clip.w;
        allBehind = allBehind && corner[i].z >= 0.0;
    }
    if (any(allOut) || allBehind) return;
    // Inside (with the margin): the camera (the origin) behind every face plane, or nearly.
    float margin = aov.insideMargin;
    bool inside = dot(corner[0], n) <= margin && dot(-corner[3], n) <= margin;
    for (int i = 0; i < 3; ++i) inside = inside && dot(-corner[i], e[i]) <= margin;
    if (inside != (aov.insidePass == 1)) return;
    gA = a;
    gB = b;
    gC = c;
    gN = n;
    emitFace(corner[0], corner[1], corner[2], corner[2], false, -n, mirrored);
    emitFace(corner[3], corner[4], corner[5], corner[5], false, n, mirrored);
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        emitFace(corner[i], corner[j], corner[j + 3], corner[i + 3], true, e[i], mirrored);
    }
}

void main() {
    vec3 a = (camera.view * vec4(gl_in[0].gl_Position.xyz, 1.0)).xyz;
    vec3 b = (camera.view * vec4(gl_in[1].gl_Position.xyz, 1.0)).xyz;
    vec3 c = (camera.view * vec4(gl_in[2].gl_Position.xyz, 1.0)).xyz;
    vec3 crossed = cross(b - a, c - a);
    float len = length(crossed);
    // Degenerate triangles occlude nothing.
    if (!(len > 1e-12 * max(dot(b - a, b - a), dot(c - a, c - a)))) return;
    bool mirrored = (vFlags[0] & AOV_DRAW_MIRRORED) != 0;
    // The front side: counter-clockwise in the model (clockwise after a mirroring matrix).
    vec3 n = (mirrored ? -crossed : crossed) / len;
    emitVolume(a, b, c, n, mirrored);
    if ((vFlags[0] & AOV_DRAW_DOUBLE_SIDED) != 0) emitVolume(a, b, c, -n, mirrored);
}
