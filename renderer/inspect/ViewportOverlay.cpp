#include "renderer/inspect/ViewportOverlay.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cmath>

#include "renderer/lighting/LightVolume.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {

bool inSubset(const OverlaySettings& s, size_t light) {
    return !s.onlySubset || std::find(s.subset.begin(), s.subset.end(), static_cast<int>(light)) != s.subset.end();
}

}  // namespace

void ViewportOverlay::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "overlay/lines.vert", .fragment = "overlay/lines.frag"});
    gl::MemoryOwner owner("viewport overlay");
    for (int k = 0; k <= kMaxSphereSubdivisions; ++k) sphere_[k].create(unitSphereVolume(k));
    cone_.create(unitConeVolume());
    lines_ = gl::Buffer::create(4096 * sizeof(glm::vec3), nullptr, true, "overlay lines");
    linesVao_ = gl::VertexArray::create();
    linesVao_.setVertexBuffer(0, lines_, 0, sizeof(glm::vec3));
    linesVao_.setAttribute(0, 0, 3, 0);
}

glm::vec4 ViewportOverlay::lightColor(const glm::vec3& intensity, bool selected) {
    if (selected) return {1.0f, 1.0f, 1.0f, 1.0f};
    const float peak = std::max({intensity.r, intensity.g, intensity.b, 1e-6f});
    const glm::vec3 c = glm::mix(glm::vec3(0.25f), intensity / peak, 0.85f);
    return {c, 1.0f};
}

void ViewportOverlay::drawLines(const std::vector<glm::vec3>& points, const glm::mat4& mvp, const glm::vec4& color) {
    if (points.empty()) return;
    gl::MemoryOwner owner("viewport overlay");
    lines_.ensureSize(points.size() * sizeof(glm::vec3), "overlay lines");
    lines_.update(0, points.size() * sizeof(glm::vec3), points.data());
    linesVao_.setVertexBuffer(0, lines_, 0, sizeof(glm::vec3));
    program_->set(0, mvp);
    program_->set(1, color);
    linesVao_.bind();
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(points.size()));
}

const gl::Texture& ViewportOverlay::compose(const gl::Texture& base, const gl::Texture* depth, const Scene& scene,
                                            const CameraUniforms& camera, const OverlaySettings& s) {
    const int w = base.width(), h = base.height();
    // The depth copy in the scene depth's format (gbuffer.depth_format).
    const GLenum depthFormat = depth && depth->internalFormat() == GL_DEPTH24_STENCIL8 ? GL_DEPTH24_STENCIL8 : GL_DEPTH32F_STENCIL8;
    if (!color_ || color_.width() != w || color_.height() != h || depth_.internalFormat() != depthFormat) {
        gl::MemoryOwner owner("viewport overlay");
        color_ = gl::Texture::create2D(GL_RGBA8, w, h);
        color_.setFilter(GL_NEAREST, GL_NEAREST);
        depth_ = gl::Texture::create2D(depthFormat, w, h);
        fbo_ = gl::Framebuffer::create("viewport overlay");
        fbo_.attachColor(0, color_);
        fbo_.attachDepth(depth_);
        fbo_.setDrawBuffers({0});
        fbo_.checkComplete("viewport overlay");
    }
    glCopyImageSubData(base.id(), GL_TEXTURE_2D, 0, 0, 0, 0, color_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, w, h, 1);
    const bool occlusion = depth && depth->width() == w && depth->height() == h && depth->internalFormat() == depthFormat;
    if (occlusion)
        glCopyImageSubData(depth->id(), GL_TEXTURE_2D, 0, 0, 0, 0, depth_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, w, h, 1);
    else
        fbo_.clearDepthStencil(DepthConvention::fromUniform(camera.depth).farDepth(), 0);

    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "viewport overlay");
    gl::resetPipelineState(w, h);
    fbo_.bind();
    program_->use();
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_CLAMP);
    const glm::mat4 vp(camera.worldToClip());  // absolute world (the overlay draws world positions) to clip
    const float sceneRadius = scene.bounds().radius();  // sizes the light markers and axes

    // Two passes: lines hidden by geometry faint, visible ones solid.
    for (int pass = 0; pass < (occlusion ? 2 : 1); ++pass) {
        const bool hidden = occlusion && pass == 0;
        const DepthConvention dc = DepthConvention::fromUniform(camera.depth);
        glDepthFunc(hidden ? dc.farther() : dc.nearerOrEqual());
        const float alpha = hidden ? 0.22f : 0.9f;
        if (s.lightVolumes) {
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            for (size_t i = 0; i < scene.lights.size(); ++i) {
                const Light& l = scene.lights[i];
                const bool selected = static_cast<int>(i) == s.selectedLight;
                if (!l.enabled || (s.onlySelected && !selected) || !inSubset(s, i)) continue;
                const LightVolume v = computeLightVolume(l, s.threshold);
                if (v.shape != VolumeShape::Sphere && v.shape != VolumeShape::Cone) continue;
                glm::vec4 c = lightColor(l.intensity, selected);
                c.a = alpha;
                program_->set(0, vp * v.transform);
                program_->set(1, c);
                (v.shape == VolumeShape::Cone ? cone_ : sphere_[std::clamp(s.sphereSubdivisions, 0, kMaxSphereSubdivisions)]).draw();
            }
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            // A small cross at every point and spot light.
            const float size = std::max(sceneRadius * 0.01f, 0.02f);
            for (size_t i = 0; i < scene.lights.size(); ++i) {
                const Light& l = scene.lights[i];
                const bool selected = static_cast<int>(i) == s.selectedLight;
                if (l.type == LightType::Directional || (s.onlySelected && !selected) || !inSubset(s, i)) continue;
                const glm::vec3 p = l.position;
                std::vector<glm::vec3> cross = {p - glm::vec3(size, 0, 0), p + glm::vec3(size, 0, 0),
                                                p - glm::vec3(0, size, 0), p + glm::vec3(0, size, 0),
                                                p - glm::vec3(0, 0, size), p + glm::vec3(0, 0, size)};
                if (l.type == LightType::Spot) {
                    cross.push_back(p);
                    cross.push_back(p + l.direction * size * 6.0f);
                }
                glm::vec4 c = lightColor(l.intensity, selected);
                c.a = l.enabled ? alpha : alpha * 0.4f;
                drawLines(cross, vp, c);
            }
        }
        if (s.axes) {
            const float len = std::max(sceneRadius * 0.25f, 1.0f);
            const glm::vec3 axis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
            for (int a = 0; a < 3; ++a) drawLines({glm::vec3(0.0f), axis[a] * len}, vp, glm::vec4(axis[a] * 0.9f + 0.1f, alpha));
        }
    }
    glPopDebugGroup();
    gl::resetPipelineState(w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return color_;
}

}  // namespace dw
