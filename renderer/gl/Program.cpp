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

namespace {

// GL 4.5's sampler and image uniform types (GL_TYPE of a GL_UNIFORM).
bool isSamplerType(GLenum t) {
    static const GLenum types[] = {
        GL_SAMPLER_1D, GL_SAMPLER_2D, GL_SAMPLER_3D, GL_SAMPLER_CUBE, GL_SAMPLER_1D_SHADOW, GL_SAMPLER_2D_SHADOW,
        GL_SAMPLER_1D_ARRAY, GL_SAMPLER_2D_ARRAY, GL_SAMPLER_1D_ARRAY_SHADOW, GL_SAMPLER_2D_ARRAY_SHADOW,
        GL_SAMPLER_2D_MULTISAMPLE, GL_SAMPLER_2D_MULTISAMPLE_ARRAY, GL_SAMPLER_CUBE_SHADOW, GL_SAMPLER_BUFFER,
        GL_SAMPLER_2D_RECT, GL_SAMPLER_2D_RECT_SHADOW, GL_SAMPLER_CUBE_MAP_ARRAY, GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW,
        GL_INT_SAMPLER_1D, GL_INT_SAMPLER_2D, GL_INT_SAMPLER_3D, GL_INT_SAMPLER_CUBE, GL_INT_SAMPLER_1D_ARRAY,
        GL_INT_SAMPLER_2D_ARRAY, GL_INT_SAMPLER_2D_MULTISAMPLE, GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY,
        GL_INT_SAMPLER_BUFFER, GL_INT_SAMPLER_2D_RECT, GL_INT_SAMPLER_CUBE_MAP_ARRAY, GL_UNSIGNED_INT_SAMPLER_1D,
        GL_UNSIGNED_INT_SAMPLER_2D, GL_UNSIGNED_INT_SAMPLER_3D, GL_UNSIGNED_INT_SAMPLER_CUBE,
        GL_UNSIGNED_INT_SAMPLER_1D_ARRAY, GL_UNSIGNED_INT_SAMPLER_2D_ARRAY, GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE,
        GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY, GL_UNSIGNED_INT_SAMPLER_BUFFER,
        GL_UNSIGNED_INT_SAMPLER_2D_RECT, GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY};
    return std::find(std::begin(types), std::end(types), t) != std::end(types);
}

bool isImageType(GLenum t) {
    static const GLenum types[] = {
        GL_IMAGE_1D, GL_IMAGE_2D, GL_IMAGE_3D, GL_IMAGE_2D_RECT, GL_IMAGE_CUBE, GL_IMAGE_BUFFER, GL_IMAGE_1D_ARRAY,
        GL_IMAGE_2D_ARRAY, GL_IMAGE_CUBE_MAP_ARRAY, GL_IMAGE_2D_MULTISAMPLE, GL_IMAGE_2D_MULTISAMPLE_ARRAY,
        GL_INT_IMAGE_1D, GL_INT_IMAGE_2D, GL_INT_IMAGE_3D, GL_INT_IMAGE_2D_RECT, GL_INT_IMAGE_CUBE,
        GL_INT_IMAGE_BUFFER, GL_INT_IMAGE_1D_ARRAY, GL_INT_IMAGE_2D_ARRAY, GL_INT_IMAGE_CUBE_MAP_ARRAY,
        GL_INT_IMAGE_2D_MULTISAMPLE, GL_INT_IMAGE_2D_MULTISAMPLE_ARRAY, GL_UNSIGNED_INT_IMAGE_1D,
        GL_UNSIGNED_INT_IMAGE_2D, GL_UNSIGNED_INT_IMAGE_3D, GL_UNSIGNED_INT_IMAGE_2D_RECT,
        GL_UNSIGNED_INT_IMAGE_CUBE, GL_UNSIGNED_INT_IMAGE_BUFFER, GL_UNSIGNED_INT_IMAGE_1D_ARRAY,
        GL_UNSIGNED_INT_IMAGE_2D_ARRAY, GL_UNSIGNED_INT_IMAGE_CUBE_MAP_ARRAY,
        GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE, GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY};
    return std::find(std::begin(types), std::end(types), t) != std::end(types);
}

std::string resourceName(GLuint program, GLenum interface, GLuint index) {
    GLint length = 0;
    const GLenum nameLength = GL_NAME_LENGTH;
    glGetProgramResourceiv(program, interface, index, 1, &nameLength, 1, nullptr, &length);
    std::string name(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramResourceName(program, interface, index, length, nullptr, name.data());
    while (!name.empty() && name.back() == '\0') name.pop_back();
    if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0) name.resize(name.size() - 3);
    return name;
}

}  // namespace

std::vector<Program::ResourceBinding> Program::resourceBindings() const {
    std::vector<ResourceBinding> out;
    using Kind = ResourceBinding::Kind;
    for (auto [interface, kind] : {std::pair{GL_UNIFORM_BLOCK, Kind::UniformBlock},
                                   std::pair{GL_SHADER_STORAGE_BLOCK, Kind::StorageBlock}}) {
        GLint count = 0;
        glGetProgramInterfaceiv(id(), interface, GL_ACTIVE_RESOURCES, &count);
        for (GLint i = 0; i < count; ++i) {
            const GLenum prop = GL_BUFFER_BINDING;
            GLint binding = -1;
            glGetProgramResourceiv(id(), interface, static_cast<GLuint>(i), 1, &prop, 1, nullptr, &binding);
            out.push_back({kind, resourceName(id(), interface, static_cast<GLuint>(i)), binding, 1});
        }
    }
    GLint uniforms = 0;
    glGetProgramInterfaceiv(id(), GL_UNIFORM, GL_ACTIVE_RESOURCES, &uniforms);
    for (GLint i = 0; i < uniforms; ++i) {
        const GLenum props[] = {GL_TYPE, GL_ARRAY_SIZE, GL_LOCATION, GL_BLOCK_INDEX};
        GLint p[4] = {};
        glGetProgramResourceiv(id(), GL_UNIFORM, static_cast<GLuint>(i), 4, props, 4, nullptr, p);
        const GLenum type = static_cast<GLenum>(p[0]);
        if (p[3] != -1 || p[2] < 0 || !(isSamplerType(type) || isImageType(type))) continue;
        GLint unit = -1;
        glGetUniformiv(id(), p[2], &unit);  // an array's first element's
        out.push_back({isSamplerType(type) ? Kind::Texture : Kind::Image,
                       resourceName(id(), GL_UNIFORM, static_cast<GLuint>(i)), unit, std::max(p[1], 1)});
    }
    return out;
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
