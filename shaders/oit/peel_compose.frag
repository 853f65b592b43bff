#version 450 core
// Depth peeling (seed 000 section 5.8): adds the layer just peeled under the
// layers before it, front to back. With the target holding (C, T) and the
// blend (GL_DST_ALPHA, GL_ONE) for colour and (GL_ZERO,
// GL_ONE_MINUS_SRC_ALPHA) for alpha, writing the layer's premultiplied
// (c, a) gives C += T c and T *= 1 - a. Counts the pixel's peeled layers.
#include "../common/bindings.glsl"
#include "../common/camera.glsl"

layout(binding = OIT_LAYER_COLOR_TEXTURE) uniform sampler2D uLayerColor;
layout(binding = OIT_LAYER_DEPTH_TEXTURE) uniform sampler2D uLayerDepth;
layout(binding = OIT_PEEL_LAYERS_IMAGE, r32ui) uniform uimage2D uLayers;  // oit.peel_layers

layout(location = 0) out vec4 outColor;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (isFarDepth(texelFetch(uLayerDepth, px, 0).r)) discard;  // nothing left to peel here
    imageStore(uLayers, px, imageLoad(uLayers, px) + uvec4(1u));
    outColor = texelFetch(uLayerColor, px, 0);
}
