#include "renderer/inspect/PixelProbe.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "renderer/inspect/OutputReadback.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/reference/ShadingReference.h"
#include "shaders/params/oit.h"

namespace dw {

namespace {

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

glm::vec4 readTexel(const gl::Texture& t, int level, int x, int yGl, int channels) {
    float v[4] = {0, 0, 0, 0};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    const bool uintFormat = isUnsignedIntegerFormat(t.internalFormat());
    if (uintFormat || isSignedIntegerFormat(t.internalFormat())) {
        // Integer textures read back only as integers.
        const GLenum format = channels == 1 ? GL_RED_INTEGER : channels == 2 ? GL_RG_INTEGER : channels == 3 ? GL_RGB_INTEGER : GL_RGBA_INTEGER;
        std::uint32_t u[4] = {0, 0, 0, 0};
        glGetTextureSubImage(t.id(), level, x, yGl, 0, 1, 1, 1, format, uintFormat ? GL_UNSIGNED_INT : GL_INT, sizeof(u), u);
        for (int c = 0; c < 4; ++c)
            v[c] = uintFormat ? static_cast<float>(u[c]) : static_cast<float>(static_cast<std::int32_t>(u[c]));
        return glm::vec4(v[0], v[1], v[2], v[3]);
    }
    const GLenum format = t.isDepth() ? GL_DEPTH_COMPONENT
                          : channels == 1 ? GL_RED
                          : channels == 2 ? GL_RG
                          : channels == 3 ? GL_RGB
                                          : GL_RGBA;
    glGetTextureSubImage(t.id(), level, x, yGl, 0, 1, 1, 1, format, GL_FLOAT, sizeof(v), v);
    glm::vec4 out(v[0], v[1], v[2], v[3]);
    if (t.isSrgb())
        for (int c = 0; c < 3; ++c) out[c] = srgbToLinear(out[c]);
    return out;
}

const ProbeValue* findValue(const ProbeResult& r, const char* name) {
    for (const auto& v : r.values)
        if (v.output == name) return &v;
    return nullptr;
}

TransparentFragment fragmentOf(const glm::vec4& premultiplied, float depth) {
    TransparentFragment f;
    f.depth = depth;
    f.alpha = premultiplied.a;
    f.colour = premultiplied.a > 0.0f ? glm::vec3(premultiplied) / premultiplied.a : glm::vec3(0.0f);
    return f;
}

// The oit pass's fragments at the pixel: the linked list walked from its
// head (links are node index + 1), or the A-buffer's first
// min(oit.sample_count, samples) samples; nearest first.
void transparentFragments(const Pipeline& pipeline, ProbeResult& r, int x, int yGl) {
    const PublishedOutput* nodes = pipeline.outputs().find("oit.list_nodes");
    if (const ProbeValue* head = findValue(r, "oit.list_heads"); head && nodes && nodes->producedThisFrame && nodes->buffer) {
        (void)x;
        (void)yGl;
        r.fragmentsFrom = "linked_list";
        auto link = static_cast<std::uint32_t>(head->raw.x);
        // A node: premultiplied RGBA as 32-bit floats, window depth, next + 1 (LinkedListOit.h).
        constexpr std::size_t kWords = gpu::OIT_LIST_NODE_WORDS, kBytes = kWords * 4;
        const std::size_t count = nodes->buffer->size() / kBytes;
        for (int guard = 0; link != 0 && link <= count && guard < 4096; ++guard) {
            std::uint32_t node[kWords];
            nodes->buffer->read((link - 1) * kBytes, sizeof node, node);
            float values[5];
            std::memcpy(values, node, sizeof values);
            r.fragments.push_back(fragmentOf(glm::vec4(values[0], values[1], values[2], values[3]), values[4]));
            link = node[5];
        }
    } else if (const ProbeValue* colour = findValue(r, "oit.abuffer")) {
        const ProbeValue* depth = findValue(r, "oit.abuffer_depth");
        const ProbeValue* count = findValue(r, "oit.sample_count");
        if (!depth || !count) return;
        r.fragmentsFrom = "abuffer";
        const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(count->raw.x), colour->samples.size());
        for (std::size_t i = 0; i < n && i < depth->samples.size(); ++i)
            r.fragments.push_back(fragmentOf(colour->samples[i], depth->samples[i].x));
    }
    const bool reversed = DepthConvention::fromUniform(pipeline.lastCamera().depth).reversed();
    std::sort(r.fragments.begin(), r.fragments.end(), [&](const TransparentFragment& a, const TransparentFragment& b) {
        return reversed ? a.depth > b.depth : a.depth < b.depth;
    });
}

}  // namespace

ProbeResult probePixel(const Pipeline& pipeline, int x, int y) {
    ProbeResult r;
    r.x = x;
    r.y = y;
    const int w = pipeline.width(), h = pipeline.height();
    r.inside = x >= 0 && y >= 0 && x < w && y < h;
    if (!r.inside) return r;
    const int yGl = h - 1 - y;
    for (const auto& o : pipeline.outputs().all()) {
        if (!o.producedThisFrame || !o.allocated()) continue;
        const ResourceKind kind = resourceKind(o);
        if (kind == ResourceKind::Buffer) {
            // A per-pixel buffer: the element under the pixel (y counted from
            // the bottom, as the shaders that write it count). Other buffers
            // (tables of lights, counters) have no pixel there: skipped.
            if (!isPerPixelBuffer(o)) continue;
            const int bw = std::max(o.desc.width, 1), bh = std::max(o.desc.height, 1);
            const std::size_t stride = std::max<std::size_t>(o.desc.stride, 4);
            const std::size_t element = static_cast<std::size_t>(std::min(yGl * bh / h, bh - 1)) * bw +
                                        static_cast<std::size_t>(std::min(x * bw / w, bw - 1));
            ProbeValue v{o.decl.name, o.decl.kind, 1, glm::vec4(0.0f), {}, {}};
            if ((element + 1) * stride > o.buffer->size()) continue;
            v.words.resize(stride / 4);
            o.buffer->read(element * stride, v.words.size() * 4, v.words.data());
            v.channels = static_cast<int>(std::min<std::size_t>(v.words.size(), 4));
            for (int c = 0; c < v.channels; ++c) {
                if (o.decl.kind == OutputKind::Count) {
                    v.raw[c] = static_cast<float>(v.words[static_cast<std::size_t>(c)]);
                } else {
                    std::memcpy(&v.raw[c], &v.words[static_cast<std::size_t>(c)], 4);
                }
            }
            r.values.push_back(std::move(v));
            continue;
        }
        // Arrays, cubes and 3D textures (shadow maps, environment maps) hold
        // other views of the scene: no texel of theirs belongs to this pixel.
        if (kind != ResourceKind::Texture2D && kind != ResourceKind::Texture2DMultisample) continue;
        const int lw = o.texture->width(o.level), lh = o.texture->height(o.level);
        // Outputs at other resolutions (mips, 1x1 statistics) are read at the same relative place.
        const int lx = std::min(x * lw / w, lw - 1), ly = std::min(yGl * lh / h, lh - 1);
        const int channels = o.texture->isDepth() ? 1 : o.channels;
        if (kind == ResourceKind::Texture2DMultisample) {
            ProbeValue v{o.decl.name, o.decl.kind, channels, glm::vec4(0.0f), readSamples(*o.texture, lx, ly, 1, 1), {}};
            for (const auto& sample : v.samples) v.raw += sample;
            v.raw /= static_cast<float>(std::max<std::size_t>(v.samples.size(), 1));
            r.values.push_back(std::move(v));
            continue;
        }
        r.values.push_back({o.decl.name, o.decl.kind, channels, readTexel(*o.texture, o.level, lx, ly, channels), {}, {}});
    }
    auto value = [&](const char* name) -> const ProbeValue* {
        for (const auto& v : r.values)
            if (v.output == name) return &v;
        return nullptr;
    };
    SurfaceSample& s = r.surface;
    const CameraUniforms& cam = pipeline.lastCamera();
    if (const ProbeValue* d = value("gbuffer.depth")) {
        s.depth = d->raw.x;
        s.background = DepthConvention::fromUniform(cam.depth).isFar(s.depth);
        // Clip depth is in [0, 1] (DepthConvention): window depth is NDC z.
        const glm::vec4 ndc((x + 0.5f) / w * 2.0f - 1.0f, (yGl + 0.5f) / h * 2.0f - 1.0f, s.depth, 1.0f);
        const glm::vec4 v = cam.inverseProjection * ndc;
        s.viewPosition = glm::vec3(v) / v.w;
        // Camera-relative rendering: view space back to world through the origin, in double.
        s.worldPosition = glm::vec3(glm::inverse(cam.worldToView()) * glm::dvec4(glm::dvec3(s.viewPosition), 1.0));
        s.linearDepth = -s.viewPosition.z;
    }
    if (const ProbeValue* n = value("gbuffer.normal"))
        s.viewNormal = glm::vec3(cam.gbuffer.x > 0.5f ? reference::decodeNormalOct(glm::dvec2(n->raw.x, n->raw.y))
                                                      : reference::decodeNormalKL(glm::dvec2(n->raw.x, n->raw.y)));
    if (const ProbeValue* a = value("gbuffer.albedo")) s.albedo = glm::vec3(a->raw);
    if (const ProbeValue* sp = value("gbuffer.specular")) {
        s.specular = glm::vec3(sp->raw);
        s.exponent = std::exp2(sp->raw.w * 11.0f);
    }
    if (const ProbeValue* e = value("gbuffer.emissive")) s.emissive = glm::vec3(e->raw);
    if (const ProbeValue* l = value("lbuffer")) {
        s.radiance = glm::vec3(l->raw);
        s.luminance = static_cast<float>(reference::luminance(l->raw.r, l->raw.g, l->raw.b));
    }
    transparentFragments(pipeline, r, x, yGl);
    return r;
}

}  // namespace dw
