#pragma once
// Per-pixel linked lists (seed 000 section 3.5 names them as the GL 4 way):
// every transparent fragment becomes a node (premultiplied colour as four
// halves, depth, next) in a node buffer of oit.list_nodes nodes, taken with
// an atomic counter and linked through a head-pointer image; the resolve
// walks a pixel's list into a local array of OIT_LIST_MAX_FRAGMENTS (32),
// sorts it and blends back to front. Exact while the budget and the bound
// hold: the reference the other methods are measured against. Fragments past
// the budget, or past the 32 nearest, are counted in oit.overflow.
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
    bool needsFragmentCount() const override { return false; }
    void render(OitFrame& frame) override;
    std::string stats() const override { return stats_; }
    static constexpr std::size_t kNodeBytes = 16;

private:
    IntKnob nodes_;
    gl::ShaderLibrary::Handle resolve_;
    TargetFramebuffer target_;
    std::string stats_;
};

}  // namespace dw
