#include "renderer/gl/Texture.h"

#include <algorithm>
#include <cmath>

#include "renderer/Error.h"

namespace dw::gl {

namespace {
GLuint createName(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    if (id == 0) throw Error("glCreateTextures failed");
    return id;
}
}  // namespace

Texture Texture::named(GLenum target, GLenum internalFormat, int width, int height, int levels, int layers) {
    Texture t;
    t.name_ = GlObject<TextureTraits>(createName(target));
    t.target_ = target;
    t.format_ = internalFormat;
    t.width_ = std::max(width, 1);
    t.height_ = std::max(height, 1);
    t.levels_ = std::max(levels, 1);
    t.layers_ = std::max(layers, 1);
    return t;
}

int Texture::fullMipCount(int width, int height) {
    int n = 1;
    int s = std::max(width, height);
    while (s > 1) {
        s /= 2;
        ++n;
    }
    return n;
}

Texture Texture::create2D(GLenum internalFormat, int width, int height, int levels) {
    Texture t = named(GL_TEXTURE_2D, internalFormat, width, height, levels, 1);
    glTextureStorage2D(t.id(), t.levels_, internalFormat, t.width_, t.height_);
    t.count();
    const bool mips = t.levels_ > 1;
    t.setFilter(mips ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    t.setWrap(GL_CLAMP_TO_EDGE);
    if (t.isDepth()) {
        // Sample the depth of a depth-stencil texture, never the stencil index.
        if (t.hasStencil()) glTextureParameteri(t.id(), GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
        t.setFilter(GL_NEAREST, GL_NEAREST);
    }
    return t;
}

Texture Texture::create2DMultisample(GLenum internalFormat, int width, int height, int samples) {
    Texture t = named(GL_TEXTURE_2D_MULTISAMPLE, internalFormat, width, height, 1, 1);
    t.samples_ = samples;
    glTextureStorage2DMultisample(t.id(), samples, internalFormat, t.width_, t.height_, GL_TRUE);
    t.count();
    return t;
}

Texture Texture::createCube(GLenum internalFormat, int size, int levels) {
    Texture t = named(GL_TEXTURE_CUBE_MAP, internalFormat, size, size, levels, 1);
    glTextureStorage2D(t.id(), t.levels_, internalFormat, t.width_, t.height_);
    t.count();
    t.setFilter(t.levels_ > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    t.setWrap(GL_CLAMP_TO_EDGE);
    if (t.isDepth()) t.setFilter(GL_NEAREST, GL_NEAREST);
    return t;
}

Texture Texture::createArray(GLenum target, GLenum internalFormat, int size, int layers) {
    Texture t = named(target, internalFormat, size, size, 1, layers);
    glTextureStorage3D(t.id(), 1, internalFormat, t.width_, t.height_, t.layers_);
    t.count();
    t.setFilter(GL_NEAREST, GL_NEAREST);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

Texture Texture::create2DArray(GLenum internalFormat, int width, int height, int layers, int levels) {
    Texture t = named(GL_TEXTURE_2D_ARRAY, internalFormat, width, height, levels, layers);
    glTextureStorage3D(t.id(), t.levels_, internalFormat, t.width_, t.height_, t.layers_);
    t.count();
    t.setFilter(GL_NEAREST, GL_NEAREST);
    t.setWrap(GL_CLAMP_TO_EDGE);
    if (t.hasStencil()) glTextureParameteri(t.id(), GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    return t;
}

Texture Texture::create3D(GLenum internalFormat, int width, int height, int depth) {
    Texture t = named(GL_TEXTURE_3D, internalFormat, width, height, 1, depth);
    glTextureStorage3D(t.id(), 1, internalFormat, t.width_, t.height_, t.layers_);
    t.count();
    t.setFilter(GL_NEAREST, GL_NEAREST);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

Texture Texture::createBuffer(GLenum internalFormat) {
    return named(GL_TEXTURE_BUFFER, internalFormat, 1, 1, 1, 1);
}

void Texture::attachBuffer(GLuint buffer) const { glTextureBuffer(id(), format_, buffer); }

Texture Texture::createView(const Texture& source, GLenum target, int firstLayer, int layers) {
    GLuint id = 0;
    glGenTextures(1, &id);  // a view needs a name that has never been bound: not glCreateTextures
    if (id == 0) throw Error("glGenTextures failed");
    glTextureView(id, target, source.id(), source.internalFormat(), 0, static_cast<GLuint>(source.levels()),
                  static_cast<GLuint>(firstLayer), static_cast<GLuint>(layers));
    Texture t;
    t.name_ = GlObject<TextureTraits>(id);
    t.target_ = target;
    t.format_ = source.format_;
    t.width_ = source.width_;
    t.height_ = source.height_;
    t.levels_ = source.levels_;
    t.layers_ = layers;
    return t;
}

void Texture::count() {
    ticket_ = LedgerTicket(MemoryLedger::instance().add(
        "texture", id(), textureStorageBytes(target_, format_, width_, height_, layers_, levels_, samples_)));
}

int Texture::width(int level) const { return std::max(width_ >> level, 1); }
int Texture::height(int level) const { return std::max(height_ >> level, 1); }

bool Texture::isDepth() const {
    switch (format_) {
        case GL_DEPTH_COMPONENT16:
        case GL_DEPTH_COMPONENT24:
        case GL_DEPTH_COMPONENT32:
        case GL_DEPTH_COMPONENT32F:
        case GL_DEPTH24_STENCIL8:
        case GL_DEPTH32F_STENCIL8:
            return true;
        default:
            return false;
    }
}

bool Texture::hasStencil() const {
    return format_ == GL_DEPTH24_STENCIL8 || format_ == GL_DEPTH32F_STENCIL8;
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) const {
    if (target_ == GL_TEXTURE_2D_MULTISAMPLE) return;
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture::setWrap(GLenum wrap) {
    if (target_ == GL_TEXTURE_2D_MULTISAMPLE) return;
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
}

void Texture::setLabel(const char* label) { glObjectLabel(GL_TEXTURE, id(), -1, label); }

void Texture::upload(int level, int width, int height, GLenum format, GLenum type,
                     const void* data) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(id(), level, 0, 0, width, height, format, type, data);
}

void Texture::uploadCubeFace(int face, int level, int size, GLenum format, GLenum type,
                             const void* data) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage3D(id(), level, 0, 0, face, size, size, 1, format, type, data);
}

void Texture::generateMipmaps() const { glGenerateTextureMipmap(id()); }

void Texture::bind(GLuint unit) const { glBindTextureUnit(unit, id()); }

std::vector<float> Texture::readFloats(int level, GLenum format, int channels) const {
    const int faces = target_ == GL_TEXTURE_CUBE_MAP ? 6 : 1;
    std::vector<float> out(static_cast<size_t>(width(level)) * height(level) * channels * faces);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(id(), level, format, GL_FLOAT, static_cast<GLsizei>(out.size() * sizeof(float)),
                      out.data());
    return out;
}

std::vector<std::uint8_t> Texture::readBytes(int level, GLenum format, int channels) const {
    std::vector<std::uint8_t> out(static_cast<size_t>(width(level)) * height(level) * channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(id(), level, format, GL_UNSIGNED_BYTE, static_cast<GLsizei>(out.size()),
                      out.data());
    return out;
}

void Texture::bindImage(GLuint unit, GLenum access) const {
    glBindImageTexture(unit, id(), 0, GL_FALSE, 0, access, format_);
}

void Texture::clearUint(unsigned value) const {
    glClearTexImage(id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}

}  // namespace dw::gl
