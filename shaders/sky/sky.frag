#version 450 core
// Sky radiance for the pixels no geometry covers (pixel type / depth says
// background, seed 000 section 5.2): a procedural gradient with a sun disc,
// or an environment map (equirectangular or cube) rotated about +Y. Covered
// pixels get 0; the lighting pass writes the sky where the G-buffer is empty.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../params/sky.h"

layout(binding = SKY_DEPTH_TEXTURE) uniform sampler2D uDepth;
layout(binding = SKY_EQUIRECT_TEXTURE) uniform sampler2D uEquirect;
layout(binding = SKY_CUBE_TEXTURE) uniform samplerCube uCube;

out vec4 outColor;

vec3 procedural(vec3 d) {
    float e = d.y;
    vec3 c = e >= 0.0 ? mix(sky.horizon, sky.zenith, pow(e, 0.45))
                      : mix(sky.horizon, sky.ground, pow(min(-e * 4.0, 1.0), 0.6));
    if (sky.hasSun != 0) {
        float cosA = dot(d, sky.sunDirection);
        float disc = smoothstep(sky.cosSunRadius - 0.00002, sky.cosSunRadius + 0.00002, cosA);
        float glow = pow(max(cosA, 0.0), 48.0) * 0.02 + pow(max(cosA, 0.0), 6.0) * 0.004;
        c += sky.sunColor * (disc + glow);
    }
    return c;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (!isFarDepth(texelFetch(uDepth, px, 0).r)) {
        outColor = vec4(0.0);
        return;
    }
    vec3 v = viewPositionAtPixel(px, 1.0);
    vec3 d = normalize(mat3(camera.inverseView) * v);
    float r = sky.rotation;
    vec3 dr = vec3(cos(r) * d.x + sin(r) * d.z, d.y, -sin(r) * d.x + cos(r) * d.z);
    vec3 c;
    if (sky.kind == SKY_KIND_EQUIRECT) {
        // Row 0 of the image (uploaded top-down) is the zenith.
        vec2 uv = vec2(0.5 + atan(dr.x, -dr.z) / (2.0 * 3.14159265), acos(clamp(dr.y, -1.0, 1.0)) / 3.14159265);
        c = textureLod(uEquirect, uv, 0.0).rgb;
    } else if (sky.kind == SKY_KIND_CUBE) {
        c = textureLod(uCube, dr, 0.0).rgb;
    } else {
        c = procedural(d);
    }
    // The sky target is half float: stay finite. Environment images are
    // sanitised at load; a scene built in code may still carry NaN (-> 0)
    // or infinities and huge values (-> 65504).
    c *= sky.intensity;
    outColor = vec4(any(isnan(c)) ? vec3(0.0) : min(max(c, vec3(0.0)), vec3(65504.0)), 1.0);
}
