#pragma once
// A linked GLSL program. Uniforms are set by explicit location
// (layout(location = N) in the shader), never looked up by string.
#include <glm/glm.hpp>
#include <vector>

#include "renderer/gl/GlObject.h"
#include "renderer/gl/ShaderSource.h"

namespace dw::gl {

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
