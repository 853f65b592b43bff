#include "renderer/oit/SortedForwardOit.h"

#include <algorithm>

#include "renderer/scene/GpuScene.h"

namespace dw {

std::string SortedForwardOit::description() const {
    return "a forward pass after lighting (seed 003 3.4): objects sorted back to front by their centres and blended "
           "over the L-buffer; wrong where objects intersect";
}

void SortedForwardOit::render(OitFrame& f) {
    FrameContext& ctx = f.ctx;
    const auto& draws = ctx.gpu.draws();
    // Distances in double precision from the camera (the frame's origin).
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t i : f.draws) {
        const Bounds& b = draws[i].bounds;
        const glm::dvec3 centre = (glm::dvec3(b.min) + glm::dvec3(b.max)) * 0.5;
        order.push_back({glm::length(centre - ctx.camera.origin), i});
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<std::size_t> sorted;
    for (const auto& [d, i] : order) sorted.push_back(i);
    std::swap(f.draws, sorted);

    gl::Framebuffer& fbo = target_.get(ctx, {"lbuffer"}, "lbuffer.depth", "oit forward");
    fbo.bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(ctx.depth().nearer());
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    f.backFacesFirst = true;  // within an object: its far faces under its near ones
    f.drawTransparent(f.transparentProgram("METHOD_FORWARD"));
    f.backFacesFirst = false;
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    std::swap(f.draws, sorted);
    stats_ = std::to_string(order.size()) + " objects sorted back to front by centre; memory " +
             mebibytes(allocatedBytes(ctx, {"oit.sample_count", "oit.overflow"})) + " (counts only)";
}

}  // namespace dw
