#include "renderer/gl/Program.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <regex>
#include <sstream>
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

// A link log names stages ("geometry shader output `vNormal' ..."), not files
// or lines: each line that names a stage gets that stage's file and, when it
// quotes an identifier (Mesa's `name'), the line of the identifier's first
// occurrence in that stage's sources, so a geometry shader's link error is
// found as its compile errors are.
std::string mapLinkLog(const std::string& log, const std::vector<ShaderStage>& stages) {
    std::istringstream in(log);
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const ShaderStage* named = nullptr;
        size_t at = std::string::npos;
        for (const auto& stage : stages) {
            const size_t pos = line.find(std::string(stageName(stage.type)) + " shader");
            if (pos != std::string::npos && pos < at) {
                at = pos;
                named = &stage;
            }
        }
        if (!named) {
            out << line << "\n";
            continue;
        }
        std::string where = named->source.mainFile().string();
        static const std::regex quoted(R"([`'"]([A-Za-z_][A-Za-z0-9_]*)')");
        std::smatch m;
        if (std::regex_search(line, m, quoted)) {
            const auto found = named->source.locate(m[1].str());
            if (found.line > 0) where = found.file.string() + ":" + std::to_string(found.line);
        }
        out << where << ": " << line << "\n";
    }
    std::string s = out.str();
    if (!s.empty() && s.back() == '\n') s.pop_back();
    return s;
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
        throw ShaderError("program (" + files + ") failed to link:\n" + mapLinkLog(infoLog(p.id(), true), stages));
    }
    return p;
}

void Program::use() const { glUseProgram(id()); }

std::vector<std::string> Program::uniformBlockNames() const {
    GLint count = 0, maxLength = 0;
    glGetProgramInterfaceiv(id(), GL_UNIFORM_BLOCK, GL_ACTIVE_RESOURCES, &count);
    glGetProgramInterfaceiv(id(), GL_UNIFORM_BLOCK, GL_MAX_NAME_LENGTH, &maxLength);
    std::vector<std::string> names;
    for (GLint i = 0; i < count; ++i) {
        std::string name(static_cast<size_t>(std::max(maxLength, 1)), '\0');
        GLsizei length = 0;
        glGetProgramResourceName(id(), GL_UNIFORM_BLOCK, static_cast<GLuint>(i), maxLength, &length, name.data());
        name.resize(static_cast<size_t>(length));
        names.push_back(name);
    }
    return names;
}

std::optional<UniformBlockLayout> Program::uniformBlock(const std::string& blockName) const {
    const GLuint block = glGetProgramResourceIndex(id(), GL_UNIFORM_BLOCK, blockName.c_str());
    if (block == GL_INVALID_INDEX) return std::nullopt;
    UniformBlockLayout layout;
    const GLenum blockProps[] = {GL_BUFFER_BINDING, GL_BUFFER_DATA_SIZE, GL_NUM_ACTIVE_VARIABLES};
    GLint values[3] = {};
    glGetProgramResourceiv(id(), GL_UNIFORM_BLOCK, block, 3, blockProps, 3, nullptr, values);
    layout.binding = values[0];
    layout.dataSize = values[1];
    std::vector<GLint> variables(static_cast<size_t>(values[2]));
    const GLenum activeVariables = GL_ACTIVE_VARIABLES;
    if (!variables.empty())
        glGetProgramResourceiv(id(), GL_UNIFORM_BLOCK, block, 1, &activeVariables, values[2], nullptr, variables.data());
    const std::string prefix = blockName + ".";
    for (GLint v : variables) {
        const GLenum props[] = {GL_NAME_LENGTH, GL_TYPE, GL_OFFSET, GL_ARRAY_SIZE, GL_ARRAY_STRIDE};
        GLint p[5] = {};
        glGetProgramResourceiv(id(), GL_UNIFORM, static_cast<GLuint>(v), 5, props, 5, nullptr, p);
        std::string name(static_cast<size_t>(std::max(p[0], 1)), '\0');
        glGetProgramResourceName(id(), GL_UNIFORM, static_cast<GLuint>(v), p[0], nullptr, name.data());
        while (!name.empty() && name.back() == '\0') name.pop_back();
        if (name.rfind(prefix, 0) == 0) name.erase(0, prefix.size());
        layout.members.push_back({name, static_cast<GLenum>(p[1]), p[2], p[3], p[4]});
    }
    return layout;
}

std::optional<Program::BufferVariable> Program::bufferVariable(const std::string& name) const {
    const GLuint v = glGetProgramResourceIndex(id(), GL_BUFFER_VARIABLE, name.c_str());
    if (v == GL_INVALID_INDEX) return std::nullopt;
    const GLenum props[] = {GL_OFFSET, GL_TOP_LEVEL_ARRAY_STRIDE};
    GLint p[2] = {};
    glGetProgramResourceiv(id(), GL_BUFFER_VARIABLE, v, 2, props, 2, nullptr, p);
    return BufferVariable{p[0], p[1]};
}

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
