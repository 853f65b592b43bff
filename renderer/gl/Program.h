#pragma once
// A linked GLSL program. Uniforms are set by explicit location
// (layout(location = N) in the shader), never looked up by string.
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "renderer/gl/GlObject.h"
#include "renderer/gl/ShaderSource.h"

namespace dw::gl {

// A uniform block as the linked program lays it out (program introspection),
// for checking it against the C++ struct that fills it.
struct UniformBlockLayout {
    struct Member {
        std::string name;       // without the block name: "radius", "kernel[0]"
        GLenum type = 0;        // GL_FLOAT, GL_INT_VEC2, ...
        GLint offset = -1;      // bytes from the start of the block
        GLint arraySize = 1;
        GLint arrayStride = 0;  // 0 when not an array
    };
    GLint binding = -1;
    GLint dataSize = 0;         // bytes the buffer must hold
    std::vector<Member> members;
};

struct ShaderStage {
    GLenum type;  // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, ...
    ShaderSource source;
};

class Program {
public:
    Program() = default;
    // Compiles and links; throws ShaderError with "path:line: message" lines.
    static Program link(const std::vector<ShaderStage>& stages);

    GLuint id() const { return name_.id(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    void use() const;

    // The layout of uniform block `blockName`, or nothing when the program
    // has no such block.
    std::optional<UniformBlockLayout> uniformBlock(const std::string& blockName) const;
    // The names of all its uniform blocks.
    std::vector<std::string> uniformBlockNames() const;
    // A storage-buffer variable ("lights[0].volume"): its byte offset in its
    // array element and the stride of the buffer's top-level array, or
    // nothing when the program does not use it (only used ones are active).
    struct BufferVariable {
        GLint offset = 0;
        GLint topLevelStride = 0;
    };
    std::optional<BufferVariable> bufferVariable(const std::string& name) const;
    // Every binding point the program uses, as introspection reports it (the
    // bindings test compares them with shaders/common/bindings.glsl's names):
    // its uniform blocks, storage blocks and active sampler and image
    // uniforms. `name` is the block's or the uniform's ("uLevels", without
    // "[0]"); `binding` the point (a sampler's texture unit, an image's image
    // unit; an array's first), `count` how many points it takes (an array's
    // length, else 1).
    struct ResourceBinding {
        enum class Kind { UniformBlock, StorageBlock, Texture, Image };
        Kind kind = Kind::UniformBlock;
        std::string name;
        GLint binding = -1;
        GLint count = 1;
    };
    std::vector<ResourceBinding> resourceBindings() const;

    void set(GLint location, int v) const;
    void set(GLint location, unsigned v) const;
    void set(GLint location, float v) const;
    void set(GLint location, const glm::vec2& v) const;
    void set(GLint location, const glm::vec3& v) const;
    void set(GLint location, const glm::vec4& v) const;
    void set(GLint location, const glm::ivec2& v) const;
    void set(GLint location, const glm::mat3& v) const;
    void set(GLint location, const glm::mat4& v) const;

private:
    GlObject<ProgramTraits> name_;
};

}  // namespace dw::gl
