#include "renderer/graph/TargetFramebuffer.h"

#include <string>
#include <vector>

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
    if (index == 0) {
        fbo.setNoColorBuffers();
    } else {
        GLint most = 0;
        glGetIntegerv(GL_MAX_DRAW_BUFFERS, &most);
        if (index > most)
            throw GlUnsupportedError(std::string(label) + ": " + std::to_string(index) + " colour targets, the driver draws at most " +
                                     std::to_string(most));
        std::vector<int> buffers(static_cast<std::size_t>(index));
        for (int i = 0; i < index; ++i) buffers[static_cast<std::size_t>(i)] = i;
        fbo.setDrawBuffers(buffers);  // the G-buffer has 5, 6 with gbuffer.directional
    }
    fbo.checkComplete(label);
    fbo_ = std::move(fbo);
    key_ = std::move(key);
    return fbo_;
}

}  // namespace dw
