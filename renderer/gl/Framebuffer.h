#pragma once
// Framebuffer object: attachments by texture, draw-buffer list, completeness
// check that names the failure, and clears without touching global state.
#include <initializer_list>
#include <vector>
#include <string>

#include "renderer/gl/GlObject.h"

namespace dw::gl {

class Texture;

class Framebuffer {
public:
    Framebuffer() = default;
    static Framebuffer create(const char* label = nullptr);
    // The common case: one colour target (a level of `texture`) as draw
    // buffer 0, checked complete (throws naming `label`).
    static Framebuffer forColor(const Texture& texture, const char* label, int level = 0);

    GLuint id() const { return name_.id(); }
    explicit operator bool() const { return static_cast<bool>(name_); }

    void attachColor(int index, const Texture& texture, int level = 0);
    void attachColorLayer(int index, const Texture& texture, int level, int layer);
    // Attaches depth, or depth+stencil when the texture format has stencil.
    void attachDepth(const Texture& texture, int level = 0);
    void attachDepthLayer(const Texture& texture, int level, int layer);
    void setDrawBuffers(std::initializer_list<int> colorIndices);
    void setDrawBuffers(const std::vector<int>& colorIndices);
    void setNoColorBuffers();
    // Throws dw::Error naming the incomplete status.
    void checkComplete(const std::string& what) const;
    void bind() const;
    static void bindDefault();

    void clearColor(int drawBuffer, float r, float g, float b, float a) const;
    void clearDepthStencil(float depth, int stencil) const;
    void clearDepth(float depth) const;
    void clearStencil(int stencil) const;

private:
    GlObject<FramebufferTraits> name_;
};

}  // namespace dw::gl
