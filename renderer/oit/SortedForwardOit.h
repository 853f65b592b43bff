#pragma once
// The sorted forward pass after deferred lighting (seed 003 section 3.4):
// the blended instances drawn back to front by the distance of their
// bounding boxes' centres from the camera (our choice; seed 000 section 3.4
// sorts triangles with a BSP tree), blended "over" straight into the
// L-buffer, depth-tested against lbuffer.depth (the G-buffer's depth copied
// by the lighting pass) without writing it. The baseline every user knows:
// where objects intersect or one's centre is nearer while its surface is
// behind, the order is wrong, and its error against the linked list shows it.
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/oit/OitMethod.h"

namespace dw {

class SortedForwardOit : public OitMethod {
public:
    explicit SortedForwardOit(KnobRegistry& knobs) { (void)knobs; }
    const char* name() const override { return "forward_sorted"; }
    std::string description() const override;
    void render(OitFrame& frame) override;
    std::string stats() const override { return stats_; }

private:
    TargetFramebuffer target_;
    std::string stats_;
};

}  // namespace dw
