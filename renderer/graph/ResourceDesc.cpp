#include "renderer/graph/ResourceDesc.h"

#include <algorithm>
#include <cstdio>

namespace dw {

const char* toString(ResourceKind kind) {
    switch (kind) {
        case ResourceKind::Texture2D: return "2D";
        case ResourceKind::Texture2DMultisample: return "2D multisample";
        case ResourceKind::Texture2DArray: return "2D array";
        case ResourceKind::TextureCube: return "cube";
        case ResourceKind::TextureCubeArray: return "cube array";
        case ResourceKind::Texture3D: return "3D";
        case ResourceKind::Buffer: return "buffer";
    }
    return "?";
}

ResourceDesc texture2D(GLenum format, int shift, int levels) {
    ResourceDesc d;
    d.format = format;
    d.shift = shift;
    d.levels = levels;
    return d;
}

ResourceDesc textureMultisample(GLenum format, int samples) {
    ResourceDesc d;
    d.kind = ResourceKind::Texture2DMultisample;
    d.format = format;
    d.samples = samples;
    return d;
}

ResourceDesc bufferPerPixel(std::size_t bytesPerPixel, std::size_t stride) {
    ResourceDesc d;
    d.kind = ResourceKind::Buffer;
    d.bytes = bytesPerPixel;
    d.stride = stride;
    return d;
}

ResourceDesc bufferFixed(std::size_t bytes, std::size_t stride) {
    ResourceDesc d;
    d.kind = ResourceKind::Buffer;
    d.size = SizeMode::Fixed;
    d.bytes = bytes;
    d.stride = stride;
    return d;
}

ResourceDesc imported() { return ResourceDesc{}; }

namespace {
std::size_t texelBytes(GLenum format) {
    switch (format) {
        case GL_R8: case GL_R8UI: return 1;
        case GL_R16F: case GL_RG8: case GL_RG8_SNORM: case GL_R16UI: case GL_DEPTH_COMPONENT16: return 2;
        case GL_RGBA8: case GL_SRGB8_ALPHA8: case GL_R32F: case GL_R32UI: case GL_RG16F: case GL_RG16_SNORM:
        case GL_R11F_G11F_B10F: case GL_DEPTH_COMPONENT32F: case GL_DEPTH_COMPONENT24: case GL_DEPTH24_STENCIL8:
        case GL_RGB10_A2: return 4;
        case GL_DEPTH32F_STENCIL8: return 5;
        case GL_RGBA16F: case GL_RG32F: case GL_RGBA16: return 8;
        case GL_RGBA32F: case GL_RGBA32UI: return 16;
        default: return 4;
    }
}
}  // namespace

std::size_t resourceBytes(const ResourceDesc& d, int fw, int fh) {
    const int w = d.size == SizeMode::Frame ? std::max(fw >> d.shift, 1) : d.width;
    const int h = d.size == SizeMode::Frame ? std::max(fh >> d.shift, 1) : d.height;
    if (d.kind == ResourceKind::Buffer)
        return d.size == SizeMode::Frame ? d.bytes * static_cast<std::size_t>(w) * static_cast<std::size_t>(h) : d.bytes;
    std::size_t level0 = texelBytes(d.format) * static_cast<std::size_t>(w) * static_cast<std::size_t>(h) *
                         static_cast<std::size_t>(std::max(d.samples, 1));
    if (d.kind == ResourceKind::Texture2DArray || d.kind == ResourceKind::TextureCubeArray || d.kind == ResourceKind::Texture3D)
        level0 *= static_cast<std::size_t>(std::max(d.layers, 1));
    if (d.kind == ResourceKind::TextureCube) level0 *= 6;
    // A mip chain adds at most a third.
    return d.levels == 1 ? level0 : level0 + level0 / 3;
}

std::string describe(const ResourceDesc& d, int fw, int fh) {
    const int w = d.size == SizeMode::Frame ? std::max(fw >> d.shift, 1) : d.width;
    const int h = d.size == SizeMode::Frame ? std::max(fh >> d.shift, 1) : d.height;
    char buf[160];
    if (d.kind == ResourceKind::Buffer) {
        const std::size_t bytes = resourceBytes(d, fw, fh);
        std::snprintf(buf, sizeof(buf), "buffer %.1f KiB (%zu B x %zu)", static_cast<double>(bytes) / 1024.0, d.stride,
                      d.stride ? bytes / d.stride : 0);
        return buf;
    }
    std::snprintf(buf, sizeof(buf), "%s 0x%04x %dx%d", toString(d.kind), static_cast<unsigned>(d.format), w, h);
    std::string s = buf;
    if (d.kind == ResourceKind::Texture2DMultisample) s += " x" + std::to_string(d.samples) + " samples";
    if (d.kind == ResourceKind::Texture2DArray || d.kind == ResourceKind::Texture3D) s += " x" + std::to_string(d.layers);
    if (d.kind == ResourceKind::TextureCubeArray) s += " x" + std::to_string(d.layers / 6) + " cubes";
    if (d.levels != 1) s += ", mips";
    return s;
}

}  // namespace dw
