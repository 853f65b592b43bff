#include "renderer/oit/LinkedListOit.h"

#include <algorithm>

#include "renderer/gl/ShaderLoopLimit.h"
#include "renderer/graph/PassTimer.h"

namespace dw {

LinkedListOit::LinkedListOit(KnobRegistry& knobs) {
    nodes_ = knobs.addInt("oit.list_nodes", 1 << 22, 1, 1 << 26, "oit",
                          "linked_list: the node buffer's size in nodes (24 bytes each; the default 4 Mi nodes is 96 MiB). "
                          "Fragments past it are lost and counted in oit.overflow",
                          "nodes", true);
}

std::string LinkedListOit::description() const {
    return "per-pixel linked lists (head-pointer image, node buffer, atomic counter), sorted per pixel in a local array "
           "of " + std::to_string(gpu::OIT_LIST_MAX_FRAGMENTS) + ": exact within oit.list_nodes, the reference";
}

std::vector<OutputDecl> LinkedListOit::outputs() const {
    return {
        {"oit.list_heads", OutputKind::Scalar, "linked_list: each pixel's first node + 1 (R32UI; 0: none)",
         texture2D(GL_R32UI), 1},
        {"oit.list_nodes", OutputKind::Scalar,
         "linked_list: the node buffer (6 words: premultiplied RGBA as 32-bit floats, window depth, next node + 1 (0: the end))",
         bufferFixed(kNodeBytes, kNodeBytes), 1},
        {"oit.list_counter", OutputKind::Count, "linked_list: nodes taken this frame (one word, the atomic counter)",
         bufferFixed(16, 4), 1},
    };
}

ResourceDesc LinkedListOit::resource(const OutputDecl& output, const KnobRegistry& knobs) const {
    if (output.name == "oit.list_nodes")
        return bufferFixed(static_cast<std::size_t>(knobs.get(nodes_)) * kNodeBytes, kNodeBytes);
    return output.resource;
}

unsigned LinkedListOit::walkLimit(int loopLimit) {
    if (loopLimit <= 0) return 0;
    const int kept = gpu::OIT_LIST_MAX_FRAGMENTS;
    // The sort (kept^2 / 2 steps and their exit tests) and the blend, with room to spare.
    const int setAside = kept * kept + 4 * kept + 1024;
    return static_cast<unsigned>(std::max(kept, (loopLimit - setAside) / (kept + 3)));
}

void LinkedListOit::setup(gl::ShaderLibrary& shaders) {
    resolve_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "oit/resolve.frag", .defines = {"RESOLVE_LIST"}});
}

void LinkedListOit::render(OitFrame& f) {
    FrameContext& ctx = f.ctx;
    const gl::Texture& heads = ctx.texture("oit.list_heads");
    const gl::Buffer& nodes = ctx.buffer("oit.list_nodes");
    const gl::Buffer& counter = ctx.buffer("oit.list_counter");
    heads.clearUint(0);
    counter.clearUint(0);
    heads.bindImage(binding::OIT_LIST_HEADS_IMAGE, GL_READ_WRITE);
    nodes.bindBase(GL_SHADER_STORAGE_BUFFER, binding::OIT_LIST_NODES_SSBO);
    counter.bindBase(GL_SHADER_STORAGE_BUFFER, binding::OIT_LIST_COUNTER_SSBO);
    const unsigned budget = static_cast<unsigned>(ctx.knobs.get(nodes_));
    f.params.nodeBudget = budget;
    const unsigned walk = walkLimit(gl::shaderLoopIterationLimit());
    f.params.walkLimit = walk;
    f.uploadParams();

    // No colour or depth writes: the fragments go to the list.
    gl::Framebuffer& fbo = target_.get(ctx, {"lbuffer"}, {}, "oit linked list");
    fbo.bind();
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    if (ctx.timer) ctx.timer->beginSubSpan("oit.list_build");
    f.drawTransparent(f.transparentProgram("METHOD_LIST"));
    if (ctx.timer) ctx.timer->endSubSpan();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (ctx.timer) ctx.timer->beginSubSpan("oit.list_resolve");
    f.compositeOverLBuffer(*resolve_);
    if (ctx.timer) ctx.timer->endSubSpan();

    unsigned taken = 0;
    counter.read(0, sizeof taken, &taken);
    const unsigned used = std::min(taken, budget);
    f.params.walkLimit = 0;
    lossCause_ = (taken > budget ? std::to_string(taken - budget) + " over oit.list_nodes = " + std::to_string(budget) + "; "
                                 : std::string()) +
                 "linked_list keeps the " + std::to_string(gpu::OIT_LIST_MAX_FRAGMENTS) + " nearest per pixel" +
                 (walk > 0 ? " of the first " + std::to_string(walk) +
                                " it walks (this driver's loop limit; a nearer one past them is lost too)"
                          : "");
    stats_ = std::to_string(used) + " of " + std::to_string(budget) + " nodes" +
             (taken > budget ? ", " + std::to_string(taken - budget) + " fragments over the budget (oit.overflow)" : "") +
             "; resolve sorts up to " + std::to_string(gpu::OIT_LIST_MAX_FRAGMENTS) + " per pixel" +
             (walk > 0 ? " of at most " + std::to_string(walk) + " walked (the driver's loop limit)" : "") + "; memory " +
             mebibytes(allocatedBytes(ctx, {"oit.list_heads", "oit.list_nodes", "oit.list_counter", "oit.sample_count",
                                            "oit.overflow"}));
}

}  // namespace dw
