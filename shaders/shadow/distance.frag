#version 450 core
// Point-light shadow maps (cube and dual paraboloid): each texel stores the
// linear distance from the light, (d - near) / (far - near) (1 minus that
// with reversed depth), the same quantity in every face and both
// hemispheres. A comparison filtered across a cube seam then compares like
// with like; with the faces' own perspective depths a receiver just past a
// seam was compared against the neighbouring face's depth of another axis
// (the one-pixel dark line of issue 10).
//
// The slope-scaled bias is applied here, as glPolygonOffset's factor would
// be (it does not act on a depth the shader writes): the depth moves away
// from the light by `slope` times its largest change per map texel.
//
// PARABOLOID: the rasterised triangle is the straight-edged image of a
// curved one (the mapping is per vertex), so the interpolated position is a
// point of the triangle's plane but not the one in this texel's direction.
// The distance is taken along the texel's own direction to that plane
// instead, exact for any planar triangle however large.
in vec3 vLightOffset;  // position minus the light's: world axes (cube) or the hemisphere's frame (paraboloid)
layout(location = 4) uniform vec4 uDistance;  // near, far, slope bias factor, 1 for reversed depth
#ifdef PARABOLOID
layout(location = 5) uniform float uMapSize;  // texels across the map
#endif

void main() {
    float dist = length(vLightOffset);
#ifdef PARABOLOID
    vec2 p = gl_FragCoord.xy / uMapSize * 2.0 - 1.0;
    float q = dot(p, p);
    vec3 dir = vec3(2.0 * p, 1.0 - q) / (1.0 + q);  // the inverse of xy / (1 + z)
    vec3 n = cross(dFdx(vLightOffset), dFdy(vLightOffset));
    float nd = dot(n, dir);
    if (abs(nd) > 1e-6 * length(n)) {
        float t = dot(n, vLightOffset) / nd;
        if (t > 0.0) dist = t;
    }
#endif
    float d = (dist - uDistance.x) / (uDistance.y - uDistance.x);
    d += uDistance.z * max(abs(dFdx(d)), abs(dFdy(d)));
    d = clamp(d, 0.0, 1.0);
    gl_FragDepth = uDistance.w > 0.5 ? 1.0 - d : d;
}
