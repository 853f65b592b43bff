#include "renderer/inspect/BufferView.h"

#include "renderer/scene/GpuScene.h"

namespace dw {

namespace {
struct ParamsGpu {
    glm::ivec4 modes{0};
    glm::ivec4 flags{0};
    glm::vec4 range{0.0f};
    glm::vec4 extra{0.0f};
};
struct RangeGpu {
    glm::vec4 lo, hi;
};
}  // namespace

void BufferView::setup(gl::ShaderLibrary& shaders) {
    view_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "bufferview/view.frag"});
    minmaxFirst_ = shaders.get({.compute = "bufferview/minmax.comp", .defines = {"FIRST_PASS"}});
    minmaxNext_ = shaders.get({.compute = "bufferview/minmax.comp"});
    params_ = gl::Buffer::create(sizeof(ParamsGpu), nullptr, true, "buffer view params");
}

BufferViewSettings::Mapping BufferView::resolveMapping(OutputKind kind, const BufferViewSettings& s) {
    using M = BufferViewSettings::Mapping;
    if (s.mapping != M::Auto) return s.mapping;
    switch (kind) {
        case OutputKind::Depth: return M::LinearDepth;
        case OutputKind::NormalKL: return M::Normal;
        case OutputKind::HdrColor: return M::Tonemap;
        case OutputKind::Count: return M::Heatmap;
        default: return M::Direct;
    }
}

bool BufferView::resolveAutoRange(OutputKind kind, const BufferViewSettings& s) {
    if (s.autoRange >= 0) return s.autoRange != 0;
    return kind == OutputKind::Depth || kind == OutputKind::Vector || kind == OutputKind::Scalar ||
           kind == OutputKind::Count;
}

const gl::Texture& BufferView::render(const PublishedOutput& output, const BufferViewSettings& s) {
    const gl::Texture& src = *output.texture;
    const int w = src.width(output.level), h = src.height(output.level);
    if (!target_ || target_.width() != w || target_.height() != h) {
        target_ = gl::Texture::create2D(GL_RGBA8, w, h);
        target_.setFilter(GL_NEAREST, GL_NEAREST);
        fbo_ = gl::Framebuffer::forColor(target_, "buffer view");
    }
    const auto mapping = resolveMapping(output.decl.kind, s);
    // One-channel buffers (AO, counts, depth) show grey rather than red.
    const BufferViewSettings::Channel channel =
        output.channels == 1 && s.channel == BufferViewSettings::Channel::RGB ? BufferViewSettings::Channel::R : s.channel;
    const bool autoRange = resolveAutoRange(output.decl.kind, s);
    ParamsGpu p;
    p.modes = glm::ivec4(static_cast<int>(mapping), static_cast<int>(channel), autoRange ? 1 : 0, output.level);
    p.flags = glm::ivec4(output.decl.kind == OutputKind::NormalKL, output.decl.kind == OutputKind::Depth,
                         src.isSrgb() ? 1 : 0, 0);
    p.range = glm::vec4(s.rangeMin, s.rangeMax, s.nearPlane, s.farPlane);
    p.extra = glm::vec4(s.exposure, 0, 0, 0);
    params_.update(0, sizeof(p), &p);
    params_.bindBase(GL_UNIFORM_BUFFER, binding::kPassUbo);

    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "buffer view");
    gl::resetPipelineState(w, h);
    src.bind(0);
    if (autoRange) {
        const size_t tiles = static_cast<size_t>((w + 15) / 16) * ((h + 15) / 16);
        if (ping_.size() < tiles * sizeof(RangeGpu)) {
            ping_ = gl::Buffer::create(tiles * sizeof(RangeGpu), nullptr, false, "view range A");
            pong_ = gl::Buffer::create(tiles * sizeof(RangeGpu), nullptr, false, "view range B");
        }
        minmaxFirst_->use();
        ping_.bindBase(GL_SHADER_STORAGE_BUFFER, 5);
        glDispatchCompute(static_cast<GLuint>((w + 15) / 16), static_cast<GLuint>((h + 15) / 16), 1);
        const gl::Buffer* in = &ping_;
        const gl::Buffer* out = &pong_;
        size_t count = tiles;
        minmaxNext_->use();
        while (count > 1) {
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            const size_t groups = (count + 255) / 256;
            in->bindBase(GL_SHADER_STORAGE_BUFFER, 4);
            out->bindBase(GL_SHADER_STORAGE_BUFFER, 5);
            minmaxNext_->set(0, static_cast<int>(count));
            glDispatchCompute(static_cast<GLuint>(groups), 1, 1);
            count = groups;
            std::swap(in, out);
        }
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        in->bindBase(GL_SHADER_STORAGE_BUFFER, 4);
        result_ = in;
    } else {
        result_ = nullptr;
    }
    fbo_.bind();
    view_->use();
    triangle_.draw();
    glPopDebugGroup();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return target_;
}

std::pair<glm::vec4, glm::vec4> BufferView::lastAutoRange() const {
    if (!result_) return {glm::vec4(0.0f), glm::vec4(1.0f)};
    RangeGpu r;
    result_->read(0, sizeof(r), &r);
    return {r.lo, r.hi};
}

}  // namespace dw
