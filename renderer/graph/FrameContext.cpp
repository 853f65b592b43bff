#include "renderer/graph/FrameContext.h"

#include "renderer/Error.h"

namespace dw {

const PublishedOutput& FrameContext::output(const std::string& name) const {
    const PublishedOutput* o = outputs.find(name);
    if (!o) throw Error("a pass reads undeclared output '" + name + "'");
    if (!o->allocated()) throw Error("output '" + name + "' is read but not allocated this frame");
    return *o;
}

const gl::Texture& FrameContext::texture(const std::string& name) const {
    const PublishedOutput& o = output(name);
    if (!o.texture) throw Error("output '" + name + "' is a buffer, not a texture");
    return *o.texture;
}

const gl::Buffer& FrameContext::buffer(const std::string& name) const {
    const PublishedOutput& o = output(name);
    if (!o.buffer) throw Error("output '" + name + "' is a texture, not a buffer");
    return *o.buffer;
}

}  // namespace dw
