#version 450 core
// Dual paraboloid shadow map (Brabec et al. 2002, seed 000 section 4.4.1):
// each hemisphere around a point light in one pass. The mapping is done per
// vertex, so large triangles bend wrongly: the known cost of the method.
layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModel;
layout(location = 2) uniform mat4 uLightView;   // world -> light frame (+Z: front hemisphere)
layout(location = 3) uniform vec4 uParams;      // near, far, hemisphere sign (+1 front, -1 back), 1 reversed depth
out gl_PerVertex { vec4 gl_Position; float gl_ClipDistance[1]; };
out vec3 vLightOffset;  // in this hemisphere's frame (+Z its axis), for shadow/distance.frag
void main() {
    vec3 v = (uLightView * uModel * vec4(aPosition, 1.0)).xyz;
    v.z *= uParams.z;
    vLightOffset = v;
    float len = length(v);
    vec3 n = len > 0.0 ? v / len : vec3(0.0, 0.0, 1.0);  // no absolute floor: a scene 1e-8 across is 1e-8 from its light
    gl_ClipDistance[0] = n.z;  // drop what lies behind this hemisphere
    // Linear in distance, in [0, 1] clip depth (reversed: 1 at near, 0 at far).
    float depth = (len - uParams.x) / (uParams.y - uParams.x);
    gl_Position = vec4(n.xy / (1.0 + n.z), uParams.w > 0.5 ? 1.0 - depth : depth, 1.0);
}
