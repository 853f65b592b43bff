#include "renderer/graph/FrameContext.h"

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/Error.h"

namespace dw {

CameraUniforms::CameraUniforms() {
    view = projection = viewProjection = inverseProjection = inverseView = glm::mat4(1.0f);
    viewport = clip = glm::vec4(0.0f);
    depth = glm::vec4(1.0f, 0.0f, 1.0f, 0.0f);
    gbuffer = glm::vec4(0.0f);
}

glm::dmat4 CameraUniforms::worldToView() const {
    return glm::translate(glm::dmat4(view), -origin);
}

glm::dmat4 CameraUniforms::worldToClip() const {
    return glm::dmat4(projection) * worldToView();
}

glm::mat4 CameraUniforms::relative(const glm::mat4& model) const {
    glm::dmat4 m(model);
    m[3] -= glm::dvec4(origin, 0.0);
    return glm::mat4(m);
}

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
