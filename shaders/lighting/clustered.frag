#version 450 core
// Clustered shading, step 3 (full screen): every surface pixel finds its
// cluster and adds the lights of the cluster's list, the same lightRadiance
// as light.frag (shade.glsl's lightRadianceAt), in one blended write.
#define CLUSTER_GRID_ACCESS readonly
#define CLUSTER_INDEX_ACCESS readonly
#define UNSHADOWED 1
#include "shade.glsl"
#include "cluster_common.glsl"

layout(location = 2) uniform int uShaded;  // candidates below this index are shaded
// This pass's entries of the cluster's list: uListFirst .. uListEnd (the
// strategy splits lists longer than the driver's loop limit over passes).
layout(location = 7) uniform int uListFirst;
layout(location = 8) uniform int uListEnd;

layout(location = 0) out vec4 outColor;
#ifdef COUNT_OVERLAP
// The lights evaluated at the pixel, added up by the blend (lighting.overlap).
layout(location = 1) out float outOverlap;
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    Surface s = readSurface(px);
    vec3 sum = vec3(0.0);
    uint shaded = 0u;
    if (isSurface(s)) {
        ClusterCell cell = cells[pixelCluster(px, -s.position.z)];
        vec3 V = normalize(-s.position);
        for (uint k = uint(uListFirst); k < min(cell.count, uint(uListEnd)); ++k) {
            uint i = clusterLights.index[cell.offset + k];
            if (int(i) >= uShaded) continue;
            // The radius test first, on one texel: most listed
            // lights miss; its distance is kept for the shading.
            vec4 pr = candidatePositionRadius(int(i));
            vec3 toLight = pr.xyz - s.position;
            float d = length(toLight);
            if (pr.w > 0.0 && d > pr.w) continue;
            Light light = candidateLight(int(i));
            vec3 L = toLight / max(d, 1e-30);
            if (!spotReaches(light, L)) continue;
            sum += lightRadianceAt(light, s, L, d, V);
            ++shaded;
        }
    }
    outColor = vec4(sum, 0.0);
#ifdef COUNT_OVERLAP
    outOverlap = float(shaded);
#endif
}
