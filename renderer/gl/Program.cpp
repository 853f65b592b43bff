#include "renderer/gl/Program.h"

#include <glm/gtc/type_ptr.hpp>
#include <string>

namespace dw::gl {

namespace {

const char* stageName(GLenum type) {
    switch (type) {
        case GL_VERTEX_SHADER: return "vertex";
        case GL_FRAGMENT_SHADER: return "fragment";
        case GL_GEOMETRY_SHADER: return "geometry";
        case GL_COMPUTE_SHADER: return "compute";
        case GL_TESS_CONTROL_SHADER: return "tessellation control";
        case GL_TESS_EVALUATION_SHADER: return "tessellation evaluation";
        default: return "unknown";
    }
}

std::string infoLog(GLuint object, bool isProgram) {
    GLint len = 0;
    if (isProgram)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &len);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
    if (isProgram)
        glGetProgramInfoLog(object, len, nullptr, log.data());
    else
        glGetShaderInfoLog(object, len, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

}  // namespace

Program Program::link(const std::vector<ShaderStage>& stages) {
    std::vector<GlObject<ShaderTraits>> shaders;
    for (const auto& stage : stages) {
        GlObject<ShaderTraits> shader(glCreateShader(stage.type));
        const char* src = stage.source.text.c_str();
        glShaderSource(shader.id(), 1, &src, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) {
            throw ShaderError(std::string(stageName(stage.type)) + " shader " +
                              stage.source.mainFile().string() + " failed to compile:\n" +
                              stage.source.mapInfoLog(infoLog(shader.id(), false)));
        }
        shaders.push_back(std::move(shader));
    }
    Program p;
    p.name_ = GlObject<ProgramTraits>(glCreateProgram());
    for (const auto& s : shaders) glAttachShader(p.id(), s.id());
    glLinkProgram(p.id());
    for (const auto& s : shaders) glDetachShader(p.id(), s.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string files;
        for (const auto& s : stages) files += (files.empty() ? "" : ", ") + s.source.mainFile().string();
        throw ShaderError("program (" + files + ") failed to link:\n" + infoLog(p.id(), true));
    }
    return p;
}

void Program::use() const { glUseProgram(id()); }

void Program::set(GLint l, int v) const { glProgramUniform1i(id(), l, v); }
void Program::set(GLint l, unsigned v) const { glProgramUniform1ui(id(), l, v); }
void Program::set(GLint l, float v) const { glProgramUniform1f(id(), l, v); }
void Program::set(GLint l, const glm::vec2& v) const { glProgramUniform2fv(id(), l, 1, glm::value_ptr(v)); }
void Program::set(GLint l, const glm::vec3& v) const { glProgramUniform3fv(id(), l, 1, glm::value_ptr(v)); }
void Program::set(GLint l, const glm::vec4& v) const { glProgramUniform4fv(id(), l, 1, glm::value_ptr(v)); }
void Program::set(GLint l, const glm::ivec2& v) const { glProgramUniform2iv(id(), l, 1, glm::value_ptr(v)); }
void Program::set(GLint l, const glm::mat3& v) const {
    glProgramUniformMatrix3fv(id(), l, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(GLint l, const glm::mat4& v) const {
    glProgramUniformMatrix4fv(id(), l, 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace dw::gl
