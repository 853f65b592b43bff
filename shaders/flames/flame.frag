#version 450 core
// A flame particle's radiance, added (blend ONE, ONE) into flames.result and
// the L-buffer at once: a soft disc (1 - r^2)^2, brighter low in the sprite,
// hidden behind the opaque surface and faded where it nears it (soft
// particles: no hard line where a sprite cuts the ground or a wall).
#include "../common/bindings.glsl"
#include "../common/camera.glsl"
#include "../params/flames.h"

layout(binding = GBUFFER_DEPTH_TEXTURE) uniform sampler2D uDepth;

in vec2 vCorner;
in vec3 vView;
flat in vec3 vEmission;

layout(location = 0) out vec4 outFlames;
layout(location = 1) out vec4 outLBuffer;

void main() {
    float r2 = dot(vCorner, vCorner);
    if (r2 >= 1.0) discard;
    float shape = (1.0 - r2) * (1.0 - r2) * (1.15 - 0.3 * (vCorner.y * 0.5 + 0.5));
    ivec2 px = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(uDepth, px, 0).r;
    float soft = 1.0;
    if (!isFarDepth(depth)) {
        float surface = -viewPositionAtPixel(px, depth).z;
        float gap = surface - (-vView.z);
        if (gap <= 0.0) discard;
        soft = clamp(gap / max(flames.softness, 1e-4), 0.0, 1.0);
    }
    vec3 c = vEmission * (shape * soft);
    outFlames = vec4(c, shape * soft);
    outLBuffer = vec4(c, 0.0);
}
