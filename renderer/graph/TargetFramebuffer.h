#pragma once
// A framebuffer over a pass's managed outputs: rebuilt only when one of them
// is re-allocated (its serial changes: a resize, a knob that changes a size),
// so passes keep no size-dependent state of their own.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "renderer/gl/Framebuffer.h"

namespace dw {

struct FrameContext;

class TargetFramebuffer {
public:
    // Colour attachments 0..n-1 from `colors` (output names, each at its
    // declared level), an optional depth(-stencil) output; all draw buffers on.
    gl::Framebuffer& get(const FrameContext& ctx, std::initializer_list<std::string> colors,
                               const std::string& depth = {}, const char* label = "pass target");

private:
    std::vector<std::uint64_t> key_;
    gl::Framebuffer fbo_;
};

}  // namespace dw
