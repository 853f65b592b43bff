#version 450 core
// glTF skinning and morphing (issue 36; renderer/scene/GpuSkinning.h): one
// invocation a vertex of one deformed mesh, writing its posed position,
// normal and tangent into the scene's vertex buffer. Operation for operation
// as poseVertices (renderer/scene/Animation.cpp), so the two agree to float
// rounding: morph deltas by the weights (a zero weight skipped), normal and
// tangent renormalised; then the weighted sum M of the joint matrices over
// JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1 (a zero weight or an out-of-range
// joint skipped; weights summing to 0 leave the vertex unskinned), position
// by M, normal by M's cofactor matrix times the sign of det (the inverse
// transpose up to a positive scale, defined when M is singular), tangent by
// M's 3x3, both renormalised.
#include "../common/bindings.glsl"

layout(local_size_x = 64) in;

struct RestVertex {
    vec4 position, normal, tangent;
};
struct Influence {
    uvec4 joints[2];
    vec4 weights[2];
};
struct Delta {
    vec4 position, normal, tangent;
};

// Vertex (renderer/scene/Mesh.h): 18 floats, position 0-2, normal 3-5, tangent 6-9.
const int VERTEX_FLOATS = 18;
layout(std430, binding = SKIN_VERTICES_SSBO) restrict writeonly buffer Vertices { float vertexData[]; };
layout(std430, binding = SKIN_REST_SSBO) restrict readonly buffer Rest { RestVertex rest[]; };
layout(std430, binding = SKIN_INFLUENCES_SSBO) restrict readonly buffer Influences { Influence influences[]; };
layout(std430, binding = SKIN_MORPH_SSBO) restrict readonly buffer Morphs { Delta deltas[]; };
layout(std430, binding = SKIN_JOINTS_SSBO) restrict readonly buffer Joints { mat4 joints[]; };
layout(std430, binding = SKIN_WEIGHTS_SSBO) restrict readonly buffer Weights { float morphWeights[]; };

layout(location = 0) uniform int uRestFirst;    // this deformer's first vertex in rest[] and influences[]
layout(location = 1) uniform int uCount;        // its vertices
layout(location = 2) uniform int uDstFirst;     // its first vertex in the vertex buffer
layout(location = 3) uniform int uJointFirst;   // its skin's first matrix in joints[]
layout(location = 4) uniform int uJointCount;   // its skin's joints; 0: not skinned
layout(location = 5) uniform int uMorphFirst;   // its deltas: deltas[uMorphFirst + target * uCount + vertex]
layout(location = 6) uniform int uTargetCount;  // weights applied; -1: the mesh has no morph targets
layout(location = 7) uniform int uWeightFirst;  // its weights in morphWeights[]

void morph(int i, inout vec3 p, inout vec3 n, inout vec3 t) {
    for (int k = 0; k < uTargetCount; ++k) {
        float w = morphWeights[uWeightFirst + k];
        if (w == 0.0) continue;
        Delta d = deltas[uMorphFirst + k * uCount + i];
        p += w * d.position.xyz;
        n += w * d.normal.xyz;
        t += w * d.tangent.xyz;
    }
    if (dot(n, n) > 0.0) n = normalize(n);
    if (dot(t, t) > 0.0) t = normalize(t);
}

// sum w_i joints[j_i]; false when the weights sum to zero.
bool skinMatrix(int i, out mat4 m) {
    m = mat4(0.0);
    float total = 0.0;
    Influence f = influences[uRestFirst + i];
    for (int set = 0; set < 2; ++set)
        for (int c = 0; c < 4; ++c) {
            float w = f.weights[set][c];
            uint j = f.joints[set][c];
            if (w != 0.0 && j < uint(uJointCount)) {
                m += w * joints[uJointFirst + int(j)];
                total += w;
            }
        }
    return total > 0.0;
}

void skin(int i, inout vec3 p, inout vec3 n, inout vec3 t) {
    mat4 m;
    if (uJointCount == 0 || !skinMatrix(i, m)) return;
    mat3 a = mat3(m);
    float s = determinant(a) < 0.0 ? -1.0 : 1.0;
    mat3 normalMatrix = s * mat3(cross(a[1], a[2]), cross(a[2], a[0]), cross(a[0], a[1]));
    p = (m * vec4(p, 1.0)).xyz;
    vec3 sn = normalMatrix * n, st = a * t;
    if (dot(sn, sn) > 0.0) n = normalize(sn);
    if (dot(st, st) > 0.0) t = normalize(st);
}

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    RestVertex r = rest[uRestFirst + i];
    vec3 p = r.position.xyz, n = r.normal.xyz, t = r.tangent.xyz;
    if (uTargetCount >= 0) morph(i, p, n, t);
    skin(i, p, n, t);
    int o = (uDstFirst + i) * VERTEX_FLOATS;
    vertexData[o + 0] = p.x;
    vertexData[o + 1] = p.y;
    vertexData[o + 2] = p.z;
    vertexData[o + 3] = n.x;
    vertexData[o + 4] = n.y;
    vertexData[o + 5] = n.z;
    vertexData[o + 6] = t.x;
    vertexData[o + 7] = t.y;
    vertexData[o + 8] = t.z;
    vertexData[o + 9] = r.tangent.w;
}
