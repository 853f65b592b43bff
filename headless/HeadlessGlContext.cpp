#include "headless/HeadlessGlContext.h"

#include <epoxy/egl.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "renderer/Error.h"

namespace dw {

namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

std::string eglErrorName(EGLint e) {
    switch (e) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "EGL error " + std::to_string(e);
    }
}

// Tries to create and make current a 4.5 core context on `display`.
EGLContext tryContext(EGLDisplay display, std::string& why) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        why = "eglInitialize failed (" + eglErrorName(eglGetError()) + ")";
        return EGL_NO_CONTEXT;
    }
    const char* ext = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(ext, "EGL_KHR_surfaceless_context")) {
        why = "no EGL_KHR_surfaceless_context";
        eglTerminate(display);
        return EGL_NO_CONTEXT;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        why = "desktop OpenGL API not available";
        eglTerminate(display);
        return EGL_NO_CONTEXT;
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(ext, "EGL_KHR_no_config_context") && !hasExtension(ext, "EGL_MESA_configless_context")) {
        const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint n = 0;
        if (!eglChooseConfig(display, attribs, &config, 1, &n) || n == 0) {
            why = "no EGL config for desktop OpenGL";
            eglTerminate(display);
            return EGL_NO_CONTEXT;
        }
    }
    const bool debug = std::getenv("DW_GL_DEBUG") && std::strcmp(std::getenv("DW_GL_DEBUG"), "0") != 0;
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
    EGLContext ctx = eglCreateContext(display, config, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx == EGL_NO_CONTEXT) {
        why = "no OpenGL 4.5 core context (" + eglErrorName(eglGetError()) + ")";
        eglTerminate(display);
        return EGL_NO_CONTEXT;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        why = "eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")";
        eglDestroyContext(display, ctx);
        eglTerminate(display);
        return EGL_NO_CONTEXT;
    }
    return ctx;
}

}  // namespace

std::unique_ptr<HeadlessGlContext> HeadlessGlContext::create() {
    const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const char* forced = std::getenv("DW_EGL_PLATFORM");
    const std::string want = forced ? forced : "";
    std::string tried;
    auto attempt = [&](const std::string& name, EGLDisplay display) -> std::unique_ptr<HeadlessGlContext> {
        if (display == EGL_NO_DISPLAY) {
            tried += "\n  " + name + ": no display";
            return nullptr;
        }
        std::string why;
        EGLContext ctx = tryContext(display, why);
        if (ctx == EGL_NO_CONTEXT) {
            tried += "\n  " + name + ": " + why;
            return nullptr;
        }
        std::unique_ptr<HeadlessGlContext> c(new HeadlessGlContext());
        c->display_ = display;
        c->context_ = ctx;
        c->platform_ = name;
        return c;
    };

    if ((want.empty() || want == "device") && hasExtension(clientExt, "EGL_EXT_platform_device") &&
        hasExtension(clientExt, "EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (eglQueryDevicesEXT(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (auto c = attempt("EGL device " + std::to_string(i), d)) return c;
            }
        }
    }
    if ((want.empty() || want == "surfaceless") && hasExtension(clientExt, "EGL_MESA_platform_surfaceless")) {
        if (auto c = attempt("EGL surfaceless", eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)))
            return c;
    }
    if (want.empty() || want == "default") {
        if (auto c = attempt("EGL default display", eglGetDisplay(EGL_DEFAULT_DISPLAY))) return c;
    }
    throw GlUnsupportedError("cannot create a headless OpenGL 4.5 core context through EGL" +
                             (tried.empty() ? std::string(" (no EGL platform available)") : ":" + tried) +
                             "\n  (Debian: apt install libegl1 libegl-mesa0 libgl1-mesa-dri)");
}

void HeadlessGlContext::makeCurrent() {
    eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_));
}

HeadlessGlContext::~HeadlessGlContext() {
    auto display = static_cast<EGLDisplay>(display_);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
}

}  // namespace dw
