#include "renderer/inspect/OutputReadback.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "renderer/Error.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Program.h"
#include "renderer/gl/Texture.h"

namespace dw {

namespace {

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

int gridColumns(int cells) {
    int c = 1;
    while (c * c < cells) ++c;
    return c;
}

// Reads layers [z0, z0 + nz) of a level as floats (integer formats converted).
std::vector<float> readTexels(const gl::Texture& t, int level, int z0, int nz, int channels) {
    const int w = t.width(level), h = t.height(level);
    const size_t count = static_cast<size_t>(w) * h * nz * channels;
    const bool uintFormat = isUnsignedIntegerFormat(t.internalFormat());
    const bool intFormat = isSignedIntegerFormat(t.internalFormat());
    GLenum format = GL_DEPTH_COMPONENT;
    if (!t.isDepth()) {
        const bool integer = uintFormat || intFormat;
        switch (channels) {
            case 1: format = integer ? GL_RED_INTEGER : GL_RED; break;
            case 2: format = integer ? GL_RG_INTEGER : GL_RG; break;
            case 3: format = integer ? GL_RGB_INTEGER : GL_RGB; break;
            default: format = integer ? GL_RGBA_INTEGER : GL_RGBA; break;
        }
    }
    std::vector<float> out(count);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    const auto bytes = static_cast<GLsizei>(count * 4);
    if (uintFormat || intFormat) {
        std::vector<std::uint32_t> words(count);
        glGetTextureSubImage(t.id(), level, 0, 0, z0, w, h, nz, format, uintFormat ? GL_UNSIGNED_INT : GL_INT, bytes,
                             words.data());
        for (size_t i = 0; i < count; ++i)
            out[i] = uintFormat ? static_cast<float>(words[i]) : static_cast<float>(static_cast<std::int32_t>(words[i]));
    } else {
        glGetTextureSubImage(t.id(), level, 0, 0, z0, w, h, nz, format, GL_FLOAT, bytes, out.data());
    }
    return out;
}

float wordValue(std::uint32_t word, bool asUint) {
    if (asUint) return static_cast<float>(word);
    float f;
    std::memcpy(&f, &word, 4);
    return f;
}

FloatImage readBufferRaw(const PublishedOutput& o, const ImageLayout& l) {
    const gl::Buffer& b = *o.buffer;
    const size_t bytes = std::min(b.size(), o.desc.bytes ? o.desc.bytes : b.size());
    std::vector<std::uint32_t> words(bytes / 4);
    if (!words.empty()) b.read(0, words.size() * 4, words.data());
    FloatImage img;
    img.width = l.width;
    img.height = l.height;
    img.channels = 1;
    img.pixels.assign(static_cast<size_t>(l.width) * l.height, 0.0f);
    for (int y = 0; y < l.height; ++y)
        for (int x = 0; x < l.width; ++x) {
            glm::ivec3 s;
            if (!l.toSource(x, y, s)) continue;
            const size_t i = (static_cast<size_t>(s.y) * l.cellWidth + s.x) * l.wordStep;
            if (i < words.size()) img.at(x, y, 0) = wordValue(words[i], l.uintWords);
        }
    img.flipVertically();
    return img;
}

// A compute shader that copies every sample of a region to a buffer (GLSL has
// no other way to read single samples). Kept here, beside its only user.
const char* const kSamplesSource = R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
#if defined(SOURCE_UINT)
layout(binding = 0) uniform usampler2DMS uSource;
#elif defined(SOURCE_INT)
layout(binding = 0) uniform isampler2DMS uSource;
#else
layout(binding = 0) uniform sampler2DMS uSource;
#endif
layout(std430, binding = 7) writeonly buffer Samples { vec4 samples[]; };
layout(location = 0) uniform ivec2 uOrigin;
layout(location = 1) uniform ivec2 uSize;
layout(location = 2) uniform int uSamples;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= uSize.x || p.y >= uSize.y) return;
    for (int s = 0; s < uSamples; ++s)
        samples[(p.y * uSize.x + p.x) * uSamples + s] = vec4(texelFetch(uSource, uOrigin + p, s));
}
)";

const gl::Program& samplesProgram(int variant) {
    // Compiled once per process and never deleted: the GL objects go with the
    // context. The label tells a program of ours from another context's name.
    static gl::Program* programs[3] = {nullptr, nullptr, nullptr};
    static const char* const kLabels[3] = {"read samples (float)", "read samples (uint)", "read samples (int)"};
    gl::Program*& p = programs[variant];
    bool valid = false;
    if (p && glIsProgram(p->id())) {
        char label[64] = {};
        GLsizei length = 0;
        glGetObjectLabel(GL_PROGRAM, p->id(), sizeof(label), &length, label);
        valid = std::strcmp(label, kLabels[variant]) == 0;
    }
    if (!valid) {
        std::vector<std::string> defines;
        if (variant == 1) defines.push_back("SOURCE_UINT");
        if (variant == 2) defines.push_back("SOURCE_INT");
        p = new gl::Program(gl::Program::link(
            {{GL_COMPUTE_SHADER, gl::ShaderSource::fromString({}, "OutputReadback.cpp:samples.comp", kSamplesSource, defines)}}));
        glObjectLabel(GL_PROGRAM, p->id(), -1, kLabels[variant]);
    }
    return *p;
}

}  // namespace

bool isUnsignedIntegerFormat(GLenum f) {
    switch (f) {
        case GL_R8UI: case GL_R16UI: case GL_R32UI: case GL_RG8UI: case GL_RG16UI: case GL_RG32UI:
        case GL_RGB8UI: case GL_RGB16UI: case GL_RGB32UI: case GL_RGBA8UI: case GL_RGBA16UI: case GL_RGBA32UI:
        case GL_RGB10_A2UI:
            return true;
        default:
            return false;
    }
}

bool isSignedIntegerFormat(GLenum f) {
    switch (f) {
        case GL_R8I: case GL_R16I: case GL_R32I: case GL_RG8I: case GL_RG16I: case GL_RG32I:
        case GL_RGB8I: case GL_RGB16I: case GL_RGB32I: case GL_RGBA8I: case GL_RGBA16I: case GL_RGBA32I:
            return true;
        default:
            return false;
    }
}

ResourceKind resourceKind(const PublishedOutput& o) {
    if (o.buffer) return ResourceKind::Buffer;
    if (!o.texture) return o.desc.kind;
    switch (o.texture->target()) {
        case GL_TEXTURE_2D_MULTISAMPLE: return ResourceKind::Texture2DMultisample;
        case GL_TEXTURE_2D_ARRAY: return ResourceKind::Texture2DArray;
        case GL_TEXTURE_CUBE_MAP: return ResourceKind::TextureCube;
        case GL_TEXTURE_CUBE_MAP_ARRAY: return ResourceKind::TextureCubeArray;
        case GL_TEXTURE_3D: return ResourceKind::Texture3D;
        default: return ResourceKind::Texture2D;
    }
}

int selectableLayers(const PublishedOutput& o) {
    if (!o.texture) return 0;
    switch (resourceKind(o)) {
        case ResourceKind::Texture2DArray: return o.texture->layers();
        case ResourceKind::Texture3D: return std::max(o.texture->layers() >> o.level, 1);
        case ResourceKind::TextureCubeArray: return std::max(o.texture->layers() / 6, 1);
        default: return 0;
    }
}

int sampleCount(const PublishedOutput& o) {
    return o.texture && resourceKind(o) == ResourceKind::Texture2DMultisample ? std::max(o.texture->samples(), 1) : 1;
}

bool isPerPixelBuffer(const PublishedOutput& o) {
    return o.buffer && o.decl.resource.kind == ResourceKind::Buffer && o.decl.resource.size == SizeMode::Frame;
}

bool ImageLayout::toSource(int x, int y, glm::ivec3& s) const {
    s = glm::ivec3(x, y, 0);
    if (arrangement == Arrangement::Plain) return true;
    if (arrangement == Arrangement::Table) {
        s = glm::ivec3(x, height - 1 - y, 0);  // element 0 in the top row
        return true;
    }
    const bool crosses = arrangement == Arrangement::Crosses;
    const glm::ivec2 cell(cellWidth * (crosses ? 4 : 1), cellHeight * (crosses ? 3 : 1));
    const glm::ivec2 c(x / cell.x, y / cell.y);
    const int rows = (cells + columns - 1) / columns;
    const int index = (rows - 1 - c.y) * columns + c.x;  // reading order from the top left
    if (index >= cells) return false;
    const glm::ivec2 local(x - c.x * cell.x, y - c.y * cell.y);
    const int layer = first + index;
    if (!crosses) {
        s = glm::ivec3(local, layer);
        return true;
    }
    const glm::ivec2 f(local.x / cellWidth, local.y / cellHeight);  // face cell, rows from the bottom
    int face = -1;
    if (f.y == 1) face = f.x == 0 ? 1 : f.x == 1 ? 4 : f.x == 2 ? 0 : 5;  // -X +Z +X -Z
    else if (f.x == 1) face = f.y == 2 ? 2 : 3;                          // +Y above, -Y below
    if (face < 0) return false;
    const glm::ivec2 t(local.x - f.x * cellWidth, local.y - f.y * cellHeight);
    s = glm::ivec3(t.x, cellHeight - 1 - t.y, layer * 6 + face);  // row t = 0 at the face's top
    return true;
}

ImageLayout imageLayout(const PublishedOutput& o, ViewSelection sel) {
    ImageLayout l;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (maxSize <= 0) maxSize = 16384;
    const ResourceKind kind = resourceKind(o);
    if (kind == ResourceKind::Buffer) {
        const ResourceDesc& d = o.desc;
        const std::size_t stride = std::max<std::size_t>(d.stride, 4);
        l.uintWords = o.decl.kind == OutputKind::Count;
        if (isPerPixelBuffer(o)) {
            l.cellWidth = std::max(d.width, 1);
            l.cellHeight = std::max(d.height, 1);
            l.wordStep = static_cast<int>(stride / 4);
        } else {
            l.arrangement = ImageLayout::Arrangement::Table;
            l.cellWidth = static_cast<int>(stride / 4);
            const std::size_t elements = std::max<std::size_t>(d.bytes / stride, 1);
            l.truncated = elements > static_cast<std::size_t>(maxSize);
            l.cellHeight = static_cast<int>(std::min<std::size_t>(elements, static_cast<std::size_t>(maxSize)));
        }
        l.width = l.cellWidth;
        l.height = l.cellHeight;
        return l;
    }
    const gl::Texture* t = o.texture;
    l.cellWidth = t ? t->width(o.level) : std::max(o.desc.width, 1);
    l.cellHeight = t ? t->height(o.level) : std::max(o.desc.height, 1);
    int layers = 0;
    switch (kind) {
        case ResourceKind::Texture2D: break;
        case ResourceKind::Texture2DMultisample:
            l.samples = sampleCount(o);
            l.sample = sel.sample >= 0 && sel.sample < l.samples ? sel.sample : -1;
            break;
        case ResourceKind::Texture2DArray:
        case ResourceKind::Texture3D:
            l.arrangement = ImageLayout::Arrangement::Layers;
            layers = selectableLayers(o);
            break;
        case ResourceKind::TextureCube:
            l.arrangement = ImageLayout::Arrangement::Crosses;
            layers = 1;
            break;
        case ResourceKind::TextureCubeArray:
            l.arrangement = ImageLayout::Arrangement::Crosses;
            layers = selectableLayers(o);
            break;
        case ResourceKind::Buffer: break;
    }
    if (l.arrangement == ImageLayout::Arrangement::Plain) {
        l.width = l.cellWidth;
        l.height = l.cellHeight;
        return l;
    }
    if (sel.layer >= 0 && sel.layer < layers) {
        l.first = sel.layer;
        l.cells = 1;
    } else {
        l.cells = std::max(layers, 1);
    }
    const bool crosses = l.arrangement == ImageLayout::Arrangement::Crosses;
    const int tileW = l.cellWidth * (crosses ? 4 : 1), tileH = l.cellHeight * (crosses ? 3 : 1);
    for (;;) {
        l.columns = gridColumns(l.cells);
        const int rows = (l.cells + l.columns - 1) / l.columns;
        l.width = l.columns * tileW;
        l.height = rows * tileH;
        if ((l.width <= maxSize && l.height <= maxSize) || l.cells == 1) break;
        --l.cells;
        l.truncated = true;
    }
    return l;
}

bool isDisplayReady(const PublishedOutput& output) {
    return output.decl.kind == OutputKind::Color && output.texture && output.texture->target() == GL_TEXTURE_2D &&
           output.texture->internalFormat() == GL_RGBA8;
}

FloatImage readOutputRaw(const PublishedOutput& output, ViewSelection selection) {
    if (!output.allocated()) throw Error("buffer '" + output.decl.name + "' has not been allocated");
    // Sources written by shader stores (buffers, images) are complete before they are read.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    const ResourceKind kind = resourceKind(output);
    if (kind == ResourceKind::Buffer) return readBufferRaw(output, imageLayout(output, selection));
    const gl::Texture& t = *output.texture;
    const bool integer = isUnsignedIntegerFormat(t.internalFormat()) || isSignedIntegerFormat(t.internalFormat());
    FloatImage img;
    if (kind == ResourceKind::Texture2D && !integer) {
        img.width = t.width(output.level);
        img.height = t.height(output.level);
        GLenum format = GL_RGBA;
        if (t.isDepth()) {
            format = GL_DEPTH_COMPONENT;
            img.channels = 1;
        } else {
            img.channels = output.channels;
            format = img.channels == 1 ? GL_RED : img.channels == 2 ? GL_RG : img.channels == 3 ? GL_RGB : GL_RGBA;
        }
        img.pixels = t.readFloats(output.level, format, img.channels);
        // Read-back returns sRGB textures' stored (encoded) values; shaders see
        // them decoded, and raw read-back means what the shaders see.
        if (t.isSrgb()) {
            for (size_t i = 0; i < img.pixels.size(); ++i) {
                if (static_cast<int>(i % img.channels) == 3) continue;
                img.pixels[i] = srgbToLinear(img.pixels[i]);
            }
        }
        img.flipVertically();
        return img;
    }
    // Every other kind: read what the layout reaches, then lay it out.
    const ImageLayout l = imageLayout(output, selection);
    const int ch = t.isDepth() ? 1 : std::clamp(output.channels, 1, 4);
    img.width = l.width;
    img.height = l.height;
    img.channels = ch;
    img.pixels.assign(static_cast<size_t>(l.width) * l.height * ch, 0.0f);
    const int w = l.cellWidth, h = l.cellHeight;
    if (kind == ResourceKind::Texture2DMultisample) {
        // texelFetch decodes sRGB itself: these are the values shaders see.
        const std::vector<glm::vec4> s = readSamples(t, 0, 0, w, h);
        const int n = l.samples;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t p = static_cast<size_t>(y) * w + x;
                glm::vec4 v(0.0f);
                if (l.sample >= 0) {
                    v = s[p * n + l.sample];
                } else {
                    for (int i = 0; i < n; ++i) v += s[p * n + i];
                    v /= static_cast<float>(n);
                }
                for (int c = 0; c < ch; ++c) img.at(x, y, c) = v[c];
            }
        img.flipVertically();
        return img;
    }
    int z0 = 0, nz = 1;
    if (l.arrangement == ImageLayout::Arrangement::Layers) {
        z0 = l.first;
        nz = l.cells;
    } else if (l.arrangement == ImageLayout::Arrangement::Crosses) {
        z0 = l.first * 6;
        nz = l.cells * 6;
    }
    const std::vector<float> texels = readTexels(t, output.level, z0, nz, ch);
    for (int y = 0; y < l.height; ++y)
        for (int x = 0; x < l.width; ++x) {
            glm::ivec3 s;
            if (!l.toSource(x, y, s)) continue;
            const size_t at = ((static_cast<size_t>(s.z - z0) * h + s.y) * w + s.x) * ch;
            for (int c = 0; c < ch; ++c) img.at(x, y, c) = texels[at + c];
        }
    if (t.isSrgb())
        for (size_t i = 0; i < img.pixels.size(); ++i)
            if (static_cast<int>(i % ch) != 3) img.pixels[i] = srgbToLinear(img.pixels[i]);
    img.flipVertically();
    return img;
}

std::vector<glm::vec4> readSamples(const gl::Texture& t, int x, int y, int width, int height) {
    if (t.target() != GL_TEXTURE_2D_MULTISAMPLE) throw Error("readSamples needs a multisample texture");
    const int n = std::max(t.samples(), 1);
    const int variant = isUnsignedIntegerFormat(t.internalFormat()) ? 1 : isSignedIntegerFormat(t.internalFormat()) ? 2 : 0;
    const gl::Program& p = samplesProgram(variant);
    const size_t count = static_cast<size_t>(width) * height * n;
    gl::MemoryOwner owner("sample read-back");
    gl::Buffer out = gl::Buffer::create(count * sizeof(glm::vec4), nullptr, false, "sample read-back");
    p.use();
    p.set(0, glm::ivec2(x, y));
    p.set(1, glm::ivec2(width, height));
    p.set(2, n);
    t.bind(0);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
    glDispatchCompute(static_cast<GLuint>((width + 7) / 8), static_cast<GLuint>((height + 7) / 8), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> v(count);
    out.read(0, count * sizeof(glm::vec4), v.data());
    glUseProgram(0);
    return v;
}

FloatImage readRgba8(const gl::Texture& texture) {
    FloatImage img;
    img.width = texture.width();
    img.height = texture.height();
    img.channels = 4;
    const auto bytes = texture.readBytes(0, GL_RGBA, 4);
    img.pixels.resize(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i) img.pixels[i] = bytes[i] / 255.0f;
    img.flipVertically();
    return img;
}

FloatImage readWindowFramebuffer(int width, int height) {
    FloatImage img;
    img.width = width;
    img.height = height;
    img.channels = 3;
    std::vector<std::uint8_t> bytes(static_cast<size_t>(width) * height * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
    img.pixels.resize(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i) img.pixels[i] = bytes[i] / 255.0f;
    img.flipVertically();
    return img;
}

std::vector<std::string> rawChannelNames(const PublishedOutput& output) {
    if (output.texture && output.texture->isDepth()) return {"Z"};
    if (output.buffer) return {"Y"};
    switch (output.channels) {
        case 1: return {"Y"};
        case 2: return {"R", "G"};
        case 3: return {"R", "G", "B"};
        default: return {"R", "G", "B", "A"};
    }
}

}  // namespace dw
