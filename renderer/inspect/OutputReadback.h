#pragma once
// Reads a named output back to CPU memory as raw float values (top-down rows),
// or as the display image the buffer view makes of it.
#include "renderer/io/ImageIO.h"
#include "renderer/graph/OutputRegistry.h"

namespace dw {

namespace gl {
class Texture;
}

// An 8-bit colour output that already holds display values (the tone-mapped
// image and what follows it), shown and saved as it is.
bool isDisplayReady(const PublishedOutput& output);
// Raw values: depth as 1 channel, KL normals as 2, colour as 3 or 4.
FloatImage readOutputRaw(const PublishedOutput& output);
// An RGBA8 texture (e.g. a buffer view) as floats in [0, 1], top-down.
FloatImage readRgba8(const gl::Texture& texture);
// The bound window's back buffer (after UI drawing, before the swap), as RGB.
FloatImage readWindowFramebuffer(int width, int height);
// EXR channel names for an output's raw read-back.
std::vector<std::string> rawChannelNames(const PublishedOutput& output);

}  // namespace dw
