#include "renderer/gl/ShaderLoopLimit.h"

#include <epoxy/gl.h>

#include <cstring>

namespace dw::gl {

int shaderLoopIterationLimit() {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (!renderer) return 0;
    return std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe") ? kMesaCpuLoopIterationLimit : 0;
}

}  // namespace dw::gl
