#pragma once
// Immutable-storage OpenGL texture (2D, 2D multisample, cube map) with
// direct-state-access helpers for upload, sampling state and read-back.
// Each storage allocation is counted in the MemoryLedger (logical bytes,
// textureStorageBytes) under the MemoryOwner in scope; views and buffer
// textures own no storage and are not counted.
#include <cstdint>
#include <vector>

#include "renderer/gl/GlObject.h"
#include "renderer/gl/MemoryLedger.h"

namespace dw::gl {

class Texture {
public:
    Texture() = default;
    static Texture create2D(GLenum internalFormat, int width, int height, int levels = 1);
    static Texture create2DMultisample(GLenum internalFormat, int width, int height, int samples);
    static Texture createCube(GLenum internalFormat, int size, int levels = 1);
    // GL_TEXTURE_2D_ARRAY (layers) or GL_TEXTURE_CUBE_MAP_ARRAY (layers = 6 x cubes).
    static Texture createArray(GLenum target, GLenum internalFormat, int size, int layers);
    static Texture create2DArray(GLenum internalFormat, int width, int height, int layers, int levels = 1);
    static Texture create3D(GLenum internalFormat, int width, int height, int depth);
    // A view (glTextureView) of `source`'s levels and layers [firstLayer,
    // firstLayer + layers) as `target` (e.g. a cube map read as a 2D array of
    // faces): same storage, sampling state of its own.
    static Texture createView(const Texture& source, GLenum target, int firstLayer, int layers);
    // A buffer texture (GL_TEXTURE_BUFFER): texelFetch over a buffer object's
    // bytes read as `internalFormat` texels. Empty until attachBuffer.
    static Texture createBuffer(GLenum internalFormat);
    // Points a buffer texture at `buffer` (again after the buffer is re-created).
    void attachBuffer(GLuint buffer) const;
    int layers() const { return layers_; }
    // Number of mip levels of a full chain down to 1x1.
    static int fullMipCount(int width, int height);

    GLuint id() const { return name_.id(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    GLenum target() const { return target_; }
    GLenum internalFormat() const { return format_; }
    int width(int level = 0) const;
    int height(int level = 0) const;
    int levels() const { return levels_; }
    int samples() const { return samples_; }
    bool isDepth() const;
    bool hasStencil() const;
    bool isSrgb() const { return format_ == GL_SRGB8_ALPHA8 || format_ == GL_SRGB8; }

    // Sampling state; const because it does not change the texture's contents.
    void setFilter(GLenum minFilter, GLenum magFilter) const;
    void setWrap(GLenum wrap);
    void setLabel(const char* label);
    void upload(int level, int width, int height, GLenum format, GLenum type, const void* data);
    void uploadCubeFace(int face, int level, int size, GLenum format, GLenum type, const void* data);
    void generateMipmaps() const;
    void bind(GLuint unit) const;
    // Level 0 as image `unit` (load/store/atomics) in the texture's own format.
    void bindImage(GLuint unit, GLenum access) const;
    // Every texel of level 0 to `value` (integer formats: GL_RED_INTEGER).
    void clearUint(unsigned value) const;

    // Reads a level back to CPU memory (rows bottom-up, as GL stores them).
    std::vector<float> readFloats(int level, GLenum format, int channels) const;
    std::vector<std::uint8_t> readBytes(int level, GLenum format, int channels) const;

private:
    // A new texture name for `target` with its description filled in (sizes
    // at least 1); the caller allocates the storage.
    static Texture named(GLenum target, GLenum internalFormat, int width, int height, int levels, int layers);
    // Counts this texture's storage in the ledger (after glTextureStorage*).
    void count();
    GlObject<TextureTraits> name_;
    LedgerTicket ticket_;
    GLenum target_ = GL_TEXTURE_2D;
    GLenum format_ = 0;
    int width_ = 0, height_ = 0, levels_ = 0, samples_ = 0, layers_ = 1;
};

}  // namespace dw::gl
