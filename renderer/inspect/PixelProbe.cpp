#include "renderer/inspect/PixelProbe.h"

#include <cmath>

#include "renderer/graph/Pipeline.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/reference/ShadingReference.h"

namespace dw {

namespace {

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

glm::vec4 readTexel(const gl::Texture& t, int level, int x, int yGl, int channels) {
    float v[4] = {0, 0, 0, 0};
    const GLenum format = t.isDepth() ? GL_DEPTH_COMPONENT
                          : channels == 1 ? GL_RED
                          : channels == 2 ? GL_RG
                          : channels == 3 ? GL_RGB
                                          : GL_RGBA;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureSubImage(t.id(), level, x, yGl, 0, 1, 1, 1, format, GL_FLOAT, sizeof(v), v);
    glm::vec4 out(v[0], v[1], v[2], v[3]);
    if (t.isSrgb())
        for (int c = 0; c < 3; ++c) out[c] = srgbToLinear(out[c]);
    return out;
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
        if (!o.producedThisFrame || !o.texture) continue;
        const int lw = o.texture->width(o.level), lh = o.texture->height(o.level);
        // Outputs at other resolutions (mips, 1x1 statistics) are read at the same relative place.
        const int lx = std::min(x * lw / w, lw - 1), ly = std::min(yGl * lh / h, lh - 1);
        r.values.push_back({o.decl.name, o.decl.kind, o.texture->isDepth() ? 1 : o.channels,
                            readTexel(*o.texture, o.level, lx, ly, o.texture->isDepth() ? 1 : o.channels)});
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
        s.background = s.depth >= 1.0f;
        const glm::vec4 ndc((x + 0.5f) / w * 2.0f - 1.0f, (yGl + 0.5f) / h * 2.0f - 1.0f, s.depth * 2.0f - 1.0f, 1.0f);
        const glm::vec4 v = cam.inverseProjection * ndc;
        s.viewPosition = glm::vec3(v) / v.w;
        s.worldPosition = glm::vec3(cam.inverseView * glm::vec4(s.viewPosition, 1.0f));
        s.linearDepth = -s.viewPosition.z;
    }
    if (const ProbeValue* n = value("gbuffer.normal"))
        s.viewNormal = glm::vec3(reference::decodeNormalKL(glm::dvec2(n->raw.x, n->raw.y)));
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
    return r;
}

}  // namespace dw
