#include "renderer/gl/Framebuffer.h"

#include <vector>

#include "renderer/Error.h"
#include "renderer/gl/Texture.h"

namespace dw::gl {

Framebuffer Framebuffer::create(const char* label) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    if (id == 0) throw Error("glCreateFramebuffers failed");
    Framebuffer fb;
    fb.name_ = GlObject<FramebufferTraits>(id);
    if (label) glObjectLabel(GL_FRAMEBUFFER, id, -1, label);
    return fb;
}

Framebuffer Framebuffer::forColor(const Texture& texture, const char* label, int level) {
    Framebuffer fb = create(label);
    fb.attachColor(0, texture, level);
    fb.setDrawBuffers({0});
    fb.checkComplete(label);
    return fb;
}

void Framebuffer::attachColor(int index, const Texture& texture, int level) {
    glNamedFramebufferTexture(id(), GL_COLOR_ATTACHMENT0 + index, texture.id(), level);
}

void Framebuffer::attachColorLayer(int index, const Texture& texture, int level, int layer) {
    glNamedFramebufferTextureLayer(id(), GL_COLOR_ATTACHMENT0 + index, texture.id(), level, layer);
}

void Framebuffer::attachDepth(const Texture& texture, int level) {
    const GLenum attachment = texture.hasStencil() ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    glNamedFramebufferTexture(id(), attachment, texture.id(), level);
}

void Framebuffer::attachDepthLayer(const Texture& texture, int level, int layer) {
    const GLenum attachment = texture.hasStencil() ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    glNamedFramebufferTextureLayer(id(), attachment, texture.id(), level, layer);
}

void Framebuffer::setDrawBuffers(std::initializer_list<int> colorIndices) { setDrawBuffers(std::vector<int>(colorIndices)); }

void Framebuffer::setDrawBuffers(const std::vector<int>& colorIndices) {
    std::vector<GLenum> bufs;
    for (int i : colorIndices) bufs.push_back(GL_COLOR_ATTACHMENT0 + i);
    glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(bufs.size()), bufs.data());
}

void Framebuffer::setNoColorBuffers() {
    glNamedFramebufferDrawBuffer(id(), GL_NONE);
    glNamedFramebufferReadBuffer(id(), GL_NONE);
}

void Framebuffer::checkComplete(const std::string& what) const {
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return;
    const char* name = "unknown status";
    switch (status) {
        case GL_FRAMEBUFFER_UNDEFINED: name = "GL_FRAMEBUFFER_UNDEFINED"; break;
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: name = "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"; break;
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            name = "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
            break;
        case GL_FRAMEBUFFER_UNSUPPORTED: name = "GL_FRAMEBUFFER_UNSUPPORTED"; break;
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            name = "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
            break;
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            name = "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
            break;
        default: break;
    }
    throw GlUnsupportedError("framebuffer '" + what + "' is incomplete on this driver: " + name);
}

void Framebuffer::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }
void Framebuffer::bindDefault() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

void Framebuffer::clearColor(int drawBuffer, float r, float g, float b, float a) const {
    const float c[4] = {r, g, b, a};
    glClearNamedFramebufferfv(id(), GL_COLOR, drawBuffer, c);
}

void Framebuffer::clearDepthStencil(float depth, int stencil) const {
    glClearNamedFramebufferfi(id(), GL_DEPTH_STENCIL, 0, depth, stencil);
}

void Framebuffer::clearDepth(float depth) const {
    glClearNamedFramebufferfv(id(), GL_DEPTH, 0, &depth);
}

void Framebuffer::clearStencil(int stencil) const {
    glClearNamedFramebufferiv(id(), GL_STENCIL, 0, &stencil);
}

}  // namespace dw::gl
