// Screen tiles and clusters as view-space volumes, and the conservative test of
// a light's bounding sphere against them, for the tiled and clustered
// strategies (seed 003 section 2.2.1; Olsson, Billeter and Assarsson 2012).
// A volume is the pixels' rectangle [pixelMin, pixelMax] (window coordinates,
// pixel edges, so every pixel centre inside lies in it) between two view-space
// depths. A sphere is kept unless it lies wholly outside one of the four side
// planes or misses the volume's bounding box (which also holds the near and
// far bounds): both tests only ever keep too much, never too little.
#ifndef TILES_GLSL
#define TILES_GLSL
#include "../common/camera.glsl"
#include "../common/lighting.glsl"
#include "../common/bindings.glsl"

// The lights a tile or cluster may take: rows of the light table. The first
// `shaded` of them are shaded by the grid, the rest (lights with a shadow map,
// shaded one at a time) are only counted.
layout(std430, binding = LIGHT_CANDIDATES_SSBO) readonly buffer LightCandidates {
    uint candidateRows[];
};

// The same candidates' light data, four texels each in candidate order:
// positionRadius, directionCutoff (a spot light's; (0, 0, 0, -1) for the
// others), intensityExponent, attenuation (see CandidateBuffers in
// renderer/lighting/LightLists.h for why texels).
layout(binding = LIGHT_CANDIDATE_DATA_TEXTURE) uniform samplerBuffer uCandidateData;

vec4 candidatePositionRadius(int i) { return texelFetch(uCandidateData, 4 * i); }
// Candidate i's direction and cos(cutoff): a spot light's, and (0, 0, 0, -1)
// for any other light (LightLists::upload), so candidateReaches needs no type.
vec4 candidateCone(int i) { return texelFetch(uCandidateData, 4 * i + 1); }
// Whether candidate light (position and radius pr, cone as candidateCone)
// reaches view-space point P, with its distance d and unit direction L
// from P: the radius test attenuate() makes and shadeLight's cone test (the
// same operations as shade.glsl's spotReaches for a spot light, always true
// for the others: dot(-L, 0) = 0 >= -1). slack widens both (0: exact).
bool candidateReaches(vec4 pr, vec4 cone, vec3 P, float slack, out float d, out vec3 L) {
    vec3 toLight = pr.xyz - P;
    d = length(toLight);
    L = toLight / max(d, 1e-30);
    return !(pr.w > 0.0 && d > pr.w * (1.0 + slack)) && dot(-L, cone.xyz) >= cone.w - slack;
}

// Candidate i as a Light with the fields spotReaches and shadeLight read;
// no volume and no shadow map.
Light candidateLight(int i) {
    Light light;
    light.volume = mat4(0.0);
    light.positionRadius = texelFetch(uCandidateData, 4 * i);
    light.directionCutoff = texelFetch(uCandidateData, 4 * i + 1);
    light.intensityExponent = texelFetch(uCandidateData, 4 * i + 2);
    light.attenuation = texelFetch(uCandidateData, 4 * i + 3);
    light.shadowMatrix = mat4(0.0);
    light.shadowParams = vec4(0.0);
    light.shadowRange = vec4(0.0);
    return light;
}

// The view-space point at depth viewZ (negative in front of the camera) on
// the ray through window position w (in pixels). Exact for perspective and
// orthographic projections alike.
vec3 pointOnPixelRay(vec2 w, float viewZ) {
    vec2 uv = w * camera.viewport.zw;
    vec3 a = viewPositionFromDepth(uv, nearPlaneDepth()), b = viewPositionFromDepth(uv, farPlaneDepth());
    return mix(a, b, (viewZ - a.z) / (b.z - a.z));
}

struct ScreenVolume {
    vec4 planes[4];  // side planes: unit outward normal, offset
    vec3 boxMin, boxMax;
};

// zNear >= zFar: the volume's view-space depth bounds (z is negative ahead).
ScreenVolume screenVolume(vec2 pixelMin, vec2 pixelMax, float zNear, float zFar) {
    ScreenVolume v;
    vec2 corner[4] = vec2[4](pixelMin, vec2(pixelMax.x, pixelMin.y), pixelMax, vec2(pixelMin.x, pixelMax.y));
    vec3 inside = pointOnPixelRay(0.5 * (pixelMin + pixelMax), 0.5 * (zNear + zFar));
    v.boxMin = vec3(1e30);
    v.boxMax = vec3(-1e30);
    vec3 near0[4], far0[4];
    for (int i = 0; i < 4; ++i) {
        vec2 uv = corner[i] * camera.viewport.zw;
        near0[i] = viewPositionFromDepth(uv, nearPlaneDepth());
        far0[i] = viewPositionFromDepth(uv, farPlaneDepth());
        vec3 p = pointOnPixelRay(corner[i], zNear), q = pointOnPixelRay(corner[i], zFar);
        v.boxMin = min(v.boxMin, min(p, q));
        v.boxMax = max(v.boxMax, max(p, q));
    }
    for (int i = 0; i < 4; ++i) {
        int j = (i + 1) & 3;
        // The plane holding the rays through corners i and j (built from the
        // near and far planes, so it exists however thin the depth range).
        vec3 n = normalize(cross(far0[i] - near0[i], near0[j] - near0[i]));
        float d = -dot(n, near0[i]);
        if (dot(n, inside) + d > 0.0) {
            n = -n;
            d = -d;
        }
        v.planes[i] = vec4(n, d);
    }
    return v;
}

// The box test alone, with r as given (no slack).
bool sphereMeetsBox(ScreenVolume v, vec3 c, float r) {
    vec3 q = clamp(c, v.boxMin, v.boxMax) - c;
    return dot(q, q) <= r * r;
}

bool sphereMeetsVolume(ScreenVolume v, vec3 c, float r) {
    // A sliver of slack for rounding: the shader lights points up to d == r.
    r = r * 1.0001 + 1e-5;
    for (int i = 0; i < 4; ++i)
        if (dot(v.planes[i].xyz, c) + v.planes[i].w > r) return false;
    return sphereMeetsBox(v, c, r);
}

// Clusters: tiles of tileSize pixels times exponential depth slices, slice k
// spanning distances near * (far/near)^(k/S) .. near * (far/near)^((k+1)/S);
// slicing = (near, S / log(far/near)). Index = (slice * tilesY + y) * tilesX + x.
int clusterSlice(float dist, vec2 slicing, int slices) {
    return clamp(int(floor(log(max(dist, slicing.x) / slicing.x) * slicing.y)), 0, slices - 1);
}

uint clusterIndex(ivec2 px, float dist, ivec2 tiles, int tileSize, vec2 slicing, int slices) {
    ivec2 t = px / tileSize;
    return uint((clusterSlice(dist, slicing, slices) * tiles.y + t.y) * tiles.x + t.x);
}

#endif
