#include "renderer/gl/Buffer.h"

#include <algorithm>

#include "renderer/Error.h"

namespace dw::gl {

Buffer Buffer::create(std::size_t bytes, const void* data, bool dynamic, const char* label) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    if (id == 0) throw Error("glCreateBuffers failed");
    Buffer b;
    b.name_ = GlObject<BufferTraits>(id);
    b.size_ = std::max<std::size_t>(bytes, 4);
    b.dynamic_ = dynamic;
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(b.size_), bytes ? data : nullptr,
                         dynamic ? GL_DYNAMIC_STORAGE_BIT : 0);
    b.ticket_ = LedgerTicket(MemoryLedger::instance().add("buffer", id, b.size_));
    if (label) glObjectLabel(GL_BUFFER, id, -1, label);
    return b;
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
    if (bytes == 0) return;
    glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::ensureSize(std::size_t bytes, const char* label) {
    if (name_ && size_ >= bytes) return;
    *this = create(std::max(bytes, size_ * 2), nullptr, true, label);
}

void Buffer::bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }

void Buffer::bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const {
    glBindBufferRange(target, index, id(), static_cast<GLintptr>(offset),
                      static_cast<GLsizeiptr>(bytes));
}

void Buffer::read(std::size_t offset, std::size_t bytes, void* out) const {
    glGetNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), out);
}

void Buffer::clearUint(unsigned value) const {
    glClearNamedBufferData(id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}

}  // namespace dw::gl
