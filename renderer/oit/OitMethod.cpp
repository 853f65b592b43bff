#include "renderer/oit/OitMethod.h"

#include <cstdio>

#include "renderer/scene/GpuScene.h"

namespace dw {


void OitFrame::drawTransparent(const gl::Program& program) const {
    program.use();
    ctx.gpu.drawInOrder(program, draws, backFacesFirst);
}

std::size_t allocatedBytes(const FrameContext& ctx, const std::vector<std::string>& names) {
    std::size_t bytes = 0;
    for (const auto& n : names) {
        const PublishedOutput* o = ctx.outputs.find(n);
        if (o && o->allocated()) bytes += resourceBytes(o->desc, ctx.width, ctx.height);
    }
    return bytes;
}

std::string mebibytes(std::size_t bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return buf;
}

}  // namespace dw
