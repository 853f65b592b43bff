#pragma once
// What a pass's output is, before it exists (DESIGN.md, "Resources and
// strategies"; Filament's FrameGraph resource descriptors): the kind of GL
// object, its format, its size (relative to the frame or fixed), samples,
// levels and layers. The pipeline allocates an output from its descriptor
// when the pass that writes it runs, re-allocates it when the descriptor
// changes (a resize, a knob such as ssao.resolution) and frees it when no pass
// that runs writes it. An output whose descriptor has no format (format 0,
// not a buffer) is imported: the pass owns it and binds it itself.
#include <cstddef>
#include <string>

#include "renderer/gl/GlObject.h"

namespace dw {

enum class ResourceKind {
    Texture2D,
    Texture2DMultisample,
    Texture2DArray,
    TextureCube,
    TextureCubeArray,  // layers = 6 x cubes
    Texture3D,
    Buffer,            // a shader storage buffer
};
const char* toString(ResourceKind kind);

enum class SizeMode {
    Frame,  // (frame width >> shift, frame height >> shift), at least 1x1
    Fixed,  // width x height
};

struct ResourceDesc {
    ResourceKind kind = ResourceKind::Texture2D;
    GLenum format = 0;  // GL internal format; 0: imported (owned by the pass)
    SizeMode size = SizeMode::Frame;
    int shift = 0;          // Frame: divide the frame size by 2^shift
    int width = 0, height = 0;
    int layers = 1;         // arrays: layers; cube arrays: 6 x cubes; 3D: depth
    int samples = 1;        // Texture2DMultisample
    int levels = 1;         // mip levels; 0: the full chain (capped by maxLevels)
    int maxLevels = 0;      // with levels = 0: at most this many (0: no cap)
    std::size_t bytes = 0;  // Buffer: size; Frame-sized buffers: bytes per pixel
    std::size_t stride = 0; // Buffer: bytes per element (the table view's rows)

    bool managed() const { return format != 0 || kind == ResourceKind::Buffer; }
    bool isTexture() const { return kind != ResourceKind::Buffer; }
    bool operator==(const ResourceDesc&) const = default;
};

// Descriptors for the common cases.
ResourceDesc texture2D(GLenum format, int shift = 0, int levels = 1);
ResourceDesc textureMultisample(GLenum format, int samples);
ResourceDesc bufferPerPixel(std::size_t bytesPerPixel, std::size_t stride);
ResourceDesc bufferFixed(std::size_t bytes, std::size_t stride);
ResourceDesc imported();

// Bytes the resource takes once allocated at `width` x `height` (frame size).
std::size_t resourceBytes(const ResourceDesc& desc, int frameWidth, int frameHeight);
// "RGBA16F 640x360", "R32UI 320x180 x4 samples", "buffer 24 KiB (96 B x 256)".
std::string describe(const ResourceDesc& desc, int frameWidth, int frameHeight);

}  // namespace dw
