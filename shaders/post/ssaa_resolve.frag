#version 450 core
// SSAA's resolve (aa.method=ssaa; seed 000 section 3.3's "render at a higher
// resolution and downscale"): each output pixel is the mean of the
// factor x factor rendered pixels over its square, a box filter (the
// footprint of the reference's `--spp N --filter box`). An sRGB-encoded
// source is averaged in linear light and encoded again.
#include "../common/bindings.glsl"
#include "../common/color.glsl"
#include "../params/ssaa.h"

layout(binding = SSAA_SOURCE_TEXTURE) uniform sampler2D uSource;

out vec4 outColor;

void main() {
    const ivec2 base = ivec2(gl_FragCoord.xy) * ssaa.factor;
    vec4 sum = vec4(0.0);
    for (int j = 0; j < ssaa.factor; ++j)
        for (int i = 0; i < ssaa.factor; ++i) {
            vec4 c = texelFetch(uSource, base + ivec2(i, j), 0);
            if (ssaa.srgbInput != 0) c.rgb = srgbToLinear(c.rgb);
            sum += c;
        }
    vec4 mean = sum / float(ssaa.factor * ssaa.factor);
    outColor = ssaa.srgbInput != 0 ? vec4(linearToSrgb(mean.rgb), mean.a) : mean;
}
