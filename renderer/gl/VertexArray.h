#pragma once
// Vertex array object with the direct-state-access attribute format calls.
#include "renderer/gl/GlObject.h"

namespace dw::gl {

class Buffer;

class VertexArray {
public:
    VertexArray() = default;
    static VertexArray create();

    GLuint id() const { return name_.id(); }
    void setVertexBuffer(GLuint binding, const Buffer& buffer, GLintptr offset, GLsizei stride);
    void setIndexBuffer(const Buffer& buffer);
    // Float attribute `location` with `components` values at `offset` in binding `binding`.
    void setAttribute(GLuint location, GLuint binding, int components, GLuint offset);
    void bind() const;

private:
    GlObject<VertexArrayTraits> name_;
};

}  // namespace dw::gl
