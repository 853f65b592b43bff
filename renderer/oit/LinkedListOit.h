#pragma once
// Per-pixel linked lists (seed 000 section 3.5 names them as the GL 4 way):
// every transparent fragment becomes a node (premultiplied colour as four
// 32-bit floats, depth, next: 24 bytes) in a node buffer of oit.list_nodes
// nodes, taken with an atomic counter and linked through a head-pointer
// image; the resolve walks a pixel's list into a local array of
// OIT_LIST_MAX_FRAGMENTS (32), sorts it and blends back to front. Exact while
// the budget and the bounds hold: the reference the other methods are
// measured against. Fragments past the budget, past the 32 nearest, or past
// the nodes one pixel's walk may read within the driver's loop budget
// (walkLimit()) are lost: every fragment is counted, so oit.overflow =
// oit.sample_count - kept, and the oit pass warns with the total.
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/oit/OitMethod.h"

namespace dw {

class LinkedListOit : public OitMethod {
public:
    explicit LinkedListOit(KnobRegistry& knobs);
    const char* name() const override { return "linked_list"; }
    std::string description() const override;
    std::vector<OutputDecl> outputs() const override;
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    bool needsFragmentCount() const override { return true; }
    void render(OitFrame& frame) override;
    std::string stats() const override { return stats_; }
    std::string lossCause() const override { return lossCause_; }
    static constexpr std::size_t kNodeBytes = 4 * gpu::OIT_LIST_NODE_WORDS;
    // The nodes one pixel's resolve walks at most on a driver whose shader
    // loops stop after `loopLimit` iterations (gl::shaderLoopIterationLimit;
    // 0: none, no bound, returns 0): each node costs the walk's iteration,
    // a rescan of the OIT_LIST_MAX_FRAGMENTS kept and its exit test, and the
    // sort and blend of the kept ones are set aside first.
    static unsigned walkLimit(int loopLimit);

private:
    IntKnob nodes_;
    gl::ShaderLibrary::Handle resolve_;
    TargetFramebuffer target_;
    std::string stats_;
    std::string lossCause_;
};

}  // namespace dw
