#include "renderer/gl/DebugOutput.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "renderer/Error.h"

namespace dw::gl {

namespace {
void GLAPIENTRY onDebugMessage(GLenum /*source*/, GLenum type, GLuint id, GLenum severity,
                               GLsizei /*length*/, const GLchar* message, const void* /*user*/) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    const char* kind = type == GL_DEBUG_TYPE_ERROR ? "error" : "message";
    std::fprintf(stderr, "GL %s %u: %s\n", kind, id, message);
}

const char* str(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? s : "?";
}
}  // namespace

GlInfo requireGl45() {
    GlInfo info;
    info.vendor = str(GL_VENDOR);
    info.renderer = str(GL_RENDERER);
    info.version = str(GL_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &info.major);
    glGetIntegerv(GL_MINOR_VERSION, &info.minor);
    if (info.major < 4 || (info.major == 4 && info.minor < 5)) {
        throw GlUnsupportedError("OpenGL 4.5 core is required, but the driver (" + info.renderer +
                                 ") provides " + info.version);
    }
    glGetIntegerv(GL_MAX_SAMPLES, &info.maxSamples);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &info.maxDrawBuffers);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &info.maxTextureSize);
    glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &info.timestampBits);
    if (info.maxDrawBuffers < 4) {
        throw GlUnsupportedError("the G-buffer needs 4 draw buffers; the driver (" + info.renderer +
                                 ") offers " + std::to_string(info.maxDrawBuffers));
    }
    if (info.timestampBits == 0) {
        throw GlUnsupportedError("the driver (" + info.renderer +
                                 ") has no GL_TIMESTAMP query counter; per-pass timing needs it");
    }
    return info;
}

bool installDebugOutput(bool force) {
    bool enabled = force;
#ifndef NDEBUG
    enabled = true;
#endif
    if (const char* env = std::getenv("DW_GL_DEBUG")) enabled = std::strcmp(env, "0") != 0;
    if (!enabled) return false;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    return true;
}

bool isCpuRasterizer(const GlInfo& info) {
    for (const char* name : {"llvmpipe", "softpipe", "SWR", "Software Rasterizer", "software rasterizer"})
        if (info.renderer.find(name) != std::string::npos) return true;
    return false;
}

}  // namespace dw::gl
