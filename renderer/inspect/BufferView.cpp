#include "renderer/inspect/BufferView.h"

#include "renderer/Error.h"
#include "renderer/scene/GpuScene.h"

namespace dw {

namespace {
struct ParamsGpu {
    glm::ivec4 modes{0};
    glm::ivec4 flags{0};
    glm::vec4 range{0.0f};
    glm::vec4 extra{0.0f};
    glm::ivec4 cell{0};    // x, y cell (layer, face) size; z first layer (cube); w sample (-1: mean)
    glm::ivec4 grid{0};    // x, y image size; z grid columns; w cells
    glm::ivec4 source{0};  // x samples; y buffer words per element step; z buffer words are unsigned
};

enum SourceKind { Source2D = 0, SourceMultisample = 1, SourceArray = 2, Source3D = 3, SourceBuffer = 4 };
const char* const kSourceDefines[] = {nullptr, "SOURCE_MS", "SOURCE_ARRAY", "SOURCE_3D", "SOURCE_BUFFER"};
const char* const kTypeDefines[] = {nullptr, "SOURCE_UINT", "SOURCE_INT"};
struct RangeGpu {
    glm::vec4 lo, hi;
};
}  // namespace

void BufferView::setup(gl::ShaderLibrary& shaders) {
    shaders_ = &shaders;
    for (auto& kind : programs_)
        for (auto& p : kind) p = {};
    programs(Source2D, 0);  // the common case now, so its errors show at start-up
    minmaxNext_ = shaders.get({.compute = "bufferview/minmax.comp"});
    params_ = gl::Buffer::create(sizeof(ParamsGpu), nullptr, true, "buffer view params");
}

const BufferView::Programs& BufferView::programs(int sourceKind, int valueType) {
    Programs& p = programs_[sourceKind][valueType];
    if (!p.view) {
        std::vector<std::string> defines;
        if (kSourceDefines[sourceKind]) defines.push_back(kSourceDefines[sourceKind]);
        if (kTypeDefines[valueType]) defines.push_back(kTypeDefines[valueType]);
        p.view = shaders_->get({.vertex = "fullscreen.vert", .fragment = "bufferview/view.frag", .defines = defines});
        defines.insert(defines.begin(), "FIRST_PASS");
        p.minmaxFirst = shaders_->get({.compute = "bufferview/minmax.comp", .defines = defines});
    }
    return p;
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
    if (!output.allocated()) throw Error("buffer '" + output.decl.name + "' has not been allocated");
    const ImageLayout layout = imageLayout(output, s.selection());
    const ResourceKind kind = resourceKind(output);
    const int w = layout.width, h = layout.height;
    if (!target_ || target_.width() != w || target_.height() != h) {
        target_ = gl::Texture::create2D(GL_RGBA8, w, h);
        target_.setFilter(GL_NEAREST, GL_NEAREST);
        fbo_ = gl::Framebuffer::forColor(target_, "buffer view");
    }
    const gl::Texture* src = output.texture;
    int sourceKind = Source2D;
    switch (kind) {
        case ResourceKind::Texture2D: break;
        case ResourceKind::Texture2DMultisample: sourceKind = SourceMultisample; break;
        case ResourceKind::Texture2DArray:
        case ResourceKind::TextureCube:
        case ResourceKind::TextureCubeArray: sourceKind = SourceArray; break;
        case ResourceKind::Texture3D: sourceKind = Source3D; break;
        case ResourceKind::Buffer: sourceKind = SourceBuffer; break;
    }
    const int valueType = !src ? 0 : isUnsignedIntegerFormat(src->internalFormat()) ? 1 : isSignedIntegerFormat(src->internalFormat()) ? 2 : 0;
    const Programs& programs = this->programs(sourceKind, valueType);
    const auto mapping = resolveMapping(output.decl.kind, s);
    // One-channel buffers (AO, counts, depth) show grey rather than red; so do buffer resources (one word a pixel).
    const int channels = kind == ResourceKind::Buffer ? 1 : output.channels;
    const BufferViewSettings::Channel channel =
        channels == 1 && s.channel == BufferViewSettings::Channel::RGB ? BufferViewSettings::Channel::R : s.channel;
    const bool autoRange = resolveAutoRange(output.decl.kind, s);
    ParamsGpu p;
    p.modes = glm::ivec4(static_cast<int>(mapping), static_cast<int>(channel), autoRange ? 1 : 0, output.level);
    p.flags = glm::ivec4(output.decl.kind == OutputKind::NormalKL, output.decl.kind == OutputKind::Depth ? (s.reversedDepth ? 2 : 1)
                         : (src && src->isDepth() && s.reversedDepth ? 3 : 0),
                         src && src->isSrgb() ? 1 : 0, static_cast<int>(layout.arrangement));
    p.range = glm::vec4(s.rangeMin, s.rangeMax, s.nearPlane, s.farPlane);
    p.extra = glm::vec4(s.exposure, 0, 0, 0);
    p.cell = glm::ivec4(layout.cellWidth, layout.cellHeight, layout.first, layout.sample);
    p.grid = glm::ivec4(w, h, layout.columns, layout.cells);
    p.source = glm::ivec4(layout.samples, layout.wordStep, layout.uintWords ? 1 : 0, 0);
    params_.update(0, sizeof(p), &p);
    params_.bindBase(GL_UNIFORM_BUFFER, binding::kPassUbo);

    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "buffer view");
    // Sources written by shader stores (buffers, images) are complete before they are read.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::resetPipelineState(w, h);
    if (sourceKind != SourceArray && sourceKind != Source3D) sourceView_ = gl::Texture();
    if (sourceKind == SourceBuffer) {
        output.buffer->bindBase(GL_SHADER_STORAGE_BUFFER, 6);
    } else if (sourceKind == SourceArray || sourceKind == Source3D) {
        // A view of all layers and levels: its own sampling state (no depth
        // compare, depth of a depth-stencil format), and cubes read as 2D arrays of faces.
        const GLenum target = sourceKind == Source3D ? GL_TEXTURE_3D : GL_TEXTURE_2D_ARRAY;
        const int layers = sourceKind == Source3D ? 1 : kind == ResourceKind::TextureCube ? 6 : src->layers();
        sourceView_ = gl::Texture::createView(*src, target, 0, layers);
        sourceView_.bind(0);
    } else {
        src->bind(0);
    }
    if (autoRange) {
        const size_t tiles = static_cast<size_t>((w + 15) / 16) * ((h + 15) / 16);
        if (ping_.size() < tiles * sizeof(RangeGpu)) {
            ping_ = gl::Buffer::create(tiles * sizeof(RangeGpu), nullptr, false, "view range A");
            pong_ = gl::Buffer::create(tiles * sizeof(RangeGpu), nullptr, false, "view range B");
        }
        programs.minmaxFirst->use();
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
    programs.view->use();
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
