#include "renderer/graph/ResourceDesc.h"

#include <algorithm>
#include <cstdio>

#include "renderer/gl/MemoryLedger.h"
#include "renderer/gl/Texture.h"

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
GLenum glTarget(ResourceKind kind) {
    switch (kind) {
        case ResourceKind::Texture2DMultisample: return GL_TEXTURE_2D_MULTISAMPLE;
        case ResourceKind::Texture2DArray: return GL_TEXTURE_2D_ARRAY;
        case ResourceKind::TextureCube: return GL_TEXTURE_CUBE_MAP;
        case ResourceKind::TextureCubeArray: return GL_TEXTURE_CUBE_MAP_ARRAY;
        case ResourceKind::Texture3D: return GL_TEXTURE_3D;
        default: return GL_TEXTURE_2D;
    }
}
}  // namespace

std::size_t resourceBytes(const ResourceDesc& d, int fw, int fh) {
    const int w = d.size == SizeMode::Frame ? std::max(fw >> d.shift, 1) : d.width;
    const int h = d.size == SizeMode::Frame ? std::max(fh >> d.shift, 1) : d.height;
    if (d.kind == ResourceKind::Buffer)
        return d.size == SizeMode::Frame ? d.bytes * static_cast<std::size_t>(w) * static_cast<std::size_t>(h) : d.bytes;
    int levels = d.levels;
    if (levels == 0) {
        levels = gl::Texture::fullMipCount(w, h);
        if (d.maxLevels > 0) levels = std::min(levels, d.maxLevels);
    }
    const int layers = d.kind == ResourceKind::TextureCube ? 1 : d.layers;
    const int samples = d.kind == ResourceKind::Texture2DMultisample ? d.samples : 1;
    // The ledger's arithmetic (gl/MemoryLedger.h): every level exactly.
    return gl::textureStorageBytes(glTarget(d.kind), d.format, w, h, layers, levels, samples);
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
