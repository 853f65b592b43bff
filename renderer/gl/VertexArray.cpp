#include "renderer/gl/VertexArray.h"

#include "renderer/Error.h"
#include "renderer/gl/Buffer.h"

namespace dw::gl {

VertexArray VertexArray::create() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    if (id == 0) throw Error("glCreateVertexArrays failed");
    VertexArray v;
    v.name_ = GlObject<VertexArrayTraits>(id);
    return v;
}

void VertexArray::setVertexBuffer(GLuint binding, const Buffer& buffer, GLintptr offset,
                                  GLsizei stride) {
    glVertexArrayVertexBuffer(id(), binding, buffer.id(), offset, stride);
}

void VertexArray::setIndexBuffer(const Buffer& buffer) {
    glVertexArrayElementBuffer(id(), buffer.id());
}

void VertexArray::setAttribute(GLuint location, GLuint binding, int components, GLuint offset) {
    glEnableVertexArrayAttrib(id(), location);
    glVertexArrayAttribFormat(id(), location, components, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(id(), location, binding);
}

void VertexArray::bind() const { glBindVertexArray(id()); }

}  // namespace dw::gl
