#include "renderer/graph/TargetFramebuffer.h"

#include <string>

#include "renderer/Error.h"
#include "renderer/graph/FrameContext.h"
#include "renderer/gl/Texture.h"

namespace dw {

gl::Framebuffer& TargetFramebuffer::get(const FrameContext& ctx, std::initializer_list<std::string> colors,
                                              const std::string& depth, const char* label) {
    std::vector<std::uint64_t> key;
    for (const auto& c : colors) key.push_back(ctx.output(c).serial);
    if (!depth.empty()) key.push_back(ctx.output(depth).serial);
    if (fbo_ && key == key_) return fbo_;
    gl::Framebuffer fbo = gl::Framebuffer::create(label);
    int index = 0;
    for (const auto& c : colors) {
        const PublishedOutput& o = ctx.output(c);
        fbo.attachColor(index++, *o.texture, o.level);
    }
    if (!depth.empty()) fbo.attachDepth(ctx.texture(depth));
    switch (index) {
        case 0: fbo.setNoColorBuffers(); break;
        case 1: fbo.setDrawBuffers({0}); break;
        case 2: fbo.setDrawBuffers({0, 1}); break;
        case 3: fbo.setDrawBuffers({0, 1, 2}); break;
        case 4: fbo.setDrawBuffers({0, 1, 2, 3}); break;
        case 5: fbo.setDrawBuffers({0, 1, 2, 3, 4}); break;  // the G-buffer with gbuffer.occlusion
        default: throw Error(std::string(label) + ": more than 5 colour targets");
    }
    fbo.checkComplete(label);
    fbo_ = std::move(fbo);
    key_ = std::move(key);
    return fbo_;
}

}  // namespace dw
