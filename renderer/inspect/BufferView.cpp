#include "renderer/inspect/BufferView.h"
#include "renderer/gl/MemoryLedger.h"

#include "renderer/Error.h"
#include "renderer/scene/GpuScene.h"
#include "shaders/params/bufferview.h"

namespace dw {

namespace {
using Mapping = BufferViewSettings::Mapping;
using Channel = BufferViewSettings::Channel;
using Arrangement = ImageLayout::Arrangement;
// The numbers the shaders compare with are declared in shaders/params/bufferview.h.
static_assert(static_cast<int>(Mapping::Direct) == gpu::VIEW_MAP_DIRECT &&
              static_cast<int>(Mapping::LinearDepth) == gpu::VIEW_MAP_LINEAR_DEPTH &&
              static_cast<int>(Mapping::Normal) == gpu::VIEW_MAP_NORMAL &&
              static_cast<int>(Mapping::Heatmap) == gpu::VIEW_MAP_HEATMAP &&
              static_cast<int>(Mapping::Tonemap) == gpu::VIEW_MAP_TONEMAP &&
              static_cast<int>(Mapping::NonFinite) == gpu::VIEW_MAP_NON_FINITE,
              "BufferViewSettings::Mapping and the VIEW_MAP_* constants differ");
static_assert(static_cast<int>(Channel::RGB) == gpu::VIEW_CHANNEL_RGB &&
              static_cast<int>(Channel::R) == gpu::VIEW_CHANNEL_R &&
              static_cast<int>(Channel::G) == gpu::VIEW_CHANNEL_G &&
              static_cast<int>(Channel::B) == gpu::VIEW_CHANNEL_B &&
              static_cast<int>(Channel::A) == gpu::VIEW_CHANNEL_A,
              "BufferViewSettings::Channel and the VIEW_CHANNEL_* constants differ");
static_assert(static_cast<int>(Arrangement::Plain) == gpu::VIEW_ARRANGE_PLAIN &&
              static_cast<int>(Arrangement::Layers) == gpu::VIEW_ARRANGE_LAYERS &&
              static_cast<int>(Arrangement::Crosses) == gpu::VIEW_ARRANGE_CROSSES &&
              static_cast<int>(Arrangement::Table) == gpu::VIEW_ARRANGE_TABLE,
              "ImageLayout::Arrangement and the VIEW_ARRANGE_* constants differ");

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
    gl::MemoryOwner owner("buffer view");
    params_.create();
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
        gl::MemoryOwner owner("buffer view");
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
    gpu::BufferViewParams p{};
    p.mapping = static_cast<int>(mapping);
    p.channel = static_cast<int>(channel);
    p.autoRange = autoRange ? 1 : 0;
    p.mipLevel = output.level;
    p.klNormal = output.decl.kind == OutputKind::NormalKL ? 1 : 0;
    if (output.decl.kind == OutputKind::Depth)
        p.depthKind = s.reversedDepth ? gpu::VIEW_DEPTH_REVERSED : gpu::VIEW_DEPTH_CONVENTIONAL;
    else if (src && src->isDepth() && s.reversedDepth)
        p.depthKind = gpu::VIEW_DEPTH_RAW_REVERSED;
    else
        p.depthKind = gpu::VIEW_DEPTH_NONE;
    p.srgb = src && src->isSrgb() ? 1 : 0;
    p.arrangement = static_cast<int>(layout.arrangement);
    p.rangeMin = s.rangeMin;
    p.rangeMax = s.rangeMax;
    p.nearPlane = s.nearPlane;
    p.farPlane = s.farPlane;
    p.exposure = s.exposure;
    p.firstLayer = layout.first;
    p.cellSize = glm::ivec2(layout.cellWidth, layout.cellHeight);
    p.viewSize = glm::ivec2(w, h);
    p.gridColumns = layout.columns;
    p.cells = layout.cells;
    p.sampleIndex = layout.sample;
    p.samples = layout.samples;
    p.wordsPerStep = layout.wordStep;
    p.unsignedWords = layout.uintWords ? 1 : 0;
    params_.upload(p, binding::PASS_UBO);

    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "buffer view");
    // Sources written by shader stores (buffers, images) are complete before they are read.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::resetPipelineState(w, h);
    if (sourceKind != SourceArray && sourceKind != Source3D) sourceView_ = gl::Texture();
    if (sourceKind == SourceBuffer) {
        output.buffer->bindBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_VIEW_SOURCE_SSBO);
    } else if (sourceKind == SourceArray || sourceKind == Source3D) {
        // A view of all layers and levels: its own sampling state (no depth
        // compare, depth of a depth-stencil format), and cubes read as 2D arrays of faces.
        const GLenum target = sourceKind == Source3D ? GL_TEXTURE_3D : GL_TEXTURE_2D_ARRAY;
        const int layers = sourceKind == Source3D ? 1 : kind == ResourceKind::TextureCube ? 6 : src->layers();
        sourceView_ = gl::Texture::createView(*src, target, 0, layers);
        sourceView_.bind(binding::BUFFER_VIEW_SOURCE_TEXTURE);
    } else {
        src->bind(binding::BUFFER_VIEW_SOURCE_TEXTURE);
    }
    if (autoRange) {
        const size_t tiles = static_cast<size_t>((w + 15) / 16) * ((h + 15) / 16);
        if (ping_.size() < tiles * sizeof(RangeGpu)) {
            gl::MemoryOwner owner("buffer view");
            ping_ = gl::Buffer::create(tiles * sizeof(RangeGpu), nullptr, false, "view range A");
            pong_ = gl::Buffer::create(tiles * sizeof(RangeGpu), nullptr, false, "view range B");
        }
        programs.minmaxFirst->use();
        ping_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_VIEW_RANGE_OUT_SSBO);
        glDispatchCompute(static_cast<GLuint>((w + 15) / 16), static_cast<GLuint>((h + 15) / 16), 1);
        const gl::Buffer* in = &ping_;
        const gl::Buffer* out = &pong_;
        size_t count = tiles;
        minmaxNext_->use();
        while (count > 1) {
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            const size_t groups = (count + 255) / 256;
            in->bindBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_VIEW_RANGE_IN_SSBO);
            out->bindBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_VIEW_RANGE_OUT_SSBO);
            minmaxNext_->set(0, static_cast<int>(count));
            glDispatchCompute(static_cast<GLuint>(groups), 1, 1);
            count = groups;
            std::swap(in, out);
        }
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        in->bindBase(GL_SHADER_STORAGE_BUFFER, binding::BUFFER_VIEW_AUTO_RANGE_SSBO);
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
