#pragma once
// The uniform buffer behind one parameter block (a dw::gpu struct declared
// with DW_PARAM_BLOCK in shaders/params/*.h): sized by the struct, written
// whole and bound in one call, so a pass never handles offsets or sizes.
#include "renderer/gl/Buffer.h"

namespace dw::gl {

template <typename Block>
class ParamBuffer {
public:
    // Call once a context exists (RenderPass::setup).
    void create() { buffer_ = Buffer::create(sizeof(Block), nullptr, true, Block::kBlockName); }
    // Writes `block` and binds the buffer at uniform binding `binding`.
    void upload(const Block& block, GLuint binding) {
        buffer_.update(0, sizeof(Block), &block);
        bind(binding);
    }
    // Binds it again (after something else used the binding point).
    void bind(GLuint binding) const { buffer_.bindBase(GL_UNIFORM_BUFFER, binding); }
    explicit operator bool() const { return static_cast<bool>(buffer_); }

private:
    Buffer buffer_;
};

}  // namespace dw::gl
