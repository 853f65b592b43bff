#include "renderer/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <glm/gtc/matrix_inverse.hpp>
#include <set>

#include "renderer/Error.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/passes/BloomPass.h"
#include "renderer/passes/DofPass.h"
#include "renderer/passes/FxaaPass.h"
#include "renderer/passes/GBufferDecodePass.h"
#include "renderer/passes/GeometryPass.h"
#include "renderer/passes/LightingPass.h"
#include "renderer/passes/LuminancePass.h"
#include "renderer/passes/SkyboxPass.h"
#include "renderer/passes/SsaoBlurPass.h"
#include "renderer/passes/SsaoPass.h"
#include "renderer/passes/TonemapPass.h"
#include "renderer/scene/Scene.h"

namespace dw {

const PassRecord* FrameReport::find(const std::string& name) const {
    for (const auto& p : passes)
        if (p.name == name) return &p;
    return nullptr;
}

Pipeline::Pipeline(KnobRegistry& knobs) : knobs_(knobs) {
    // Seed 002 section 6: G-buffer, SSAO, (transparency), L-buffer (the sky
    // and the shadow maps feed it), luminance statistics, bloom, tone mapping;
    // then depth of field and FXAA on the tone-mapped image.
    passes_.push_back(std::make_unique<GeometryPass>(knobs));
    passes_.push_back(std::make_unique<GBufferDecodePass>(knobs));
    passes_.push_back(std::make_unique<SsaoPass>(knobs));
    passes_.push_back(std::make_unique<SsaoBlurPass>(knobs));
    passes_.push_back(std::make_unique<SkyboxPass>(knobs));
    passes_.push_back(std::make_unique<LightingPass>(knobs));
    passes_.push_back(std::make_unique<LuminancePass>(knobs));
    passes_.push_back(std::make_unique<BloomPass>(knobs));
    passes_.push_back(std::make_unique<TonemapPass>(knobs));
    passes_.push_back(std::make_unique<DofPass>(knobs));
    passes_.push_back(std::make_unique<FxaaPass>(knobs));
    for (const auto& p : passes_)
        for (const auto& o : p->outputs()) outputs_.declare(p->name(), o);
    outputs_.declare("tonemap", {kFinalOutput, OutputKind::Color,
                                 "the display image: fxaa.result, dof.result or tonemap.result, whichever post pass ran last"});
}

std::string Pipeline::resolveFinal() const {
    for (const char* candidate : kFinalChain) {
        const PublishedOutput* o = outputs_.find(candidate);
        if (!o) continue;
        const RenderPass* p = findPass(o->pass);
        if (p && (!scene_ || p->skipReason(knobs_, *scene_).empty())) return candidate;
    }
    return kFinalChain[std::size(kFinalChain) - 1];
}

Pipeline::~Pipeline() = default;

RenderPass* Pipeline::findPass(const std::string& name) const {
    for (const auto& p : passes_)
        if (name == p->name()) return p.get();
    return nullptr;
}

void Pipeline::setup(gl::ShaderLibrary& shaders) {
    shaders_ = &shaders;
    for (auto& p : passes_) p->setup(shaders);
    cameraUbo_ = gl::Buffer::create(sizeof(CameraUniforms), nullptr, true, "camera");
}

void Pipeline::setScene(const Scene& scene) {
    // Build the new GPU copy aside, so a failure keeps the previous scene.
    GpuScene next;
    next.upload(scene);
    gpu_ = std::move(next);
    scene_ = &scene;
}

void Pipeline::resize(int width, int height) {
    if (width <= 0 || height <= 0) throw Error("render size must be positive");
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    for (auto& p : passes_) p->resize(width, height, outputs_);
}

CameraUniforms Pipeline::cameraUniforms(const Camera& camera, int width, int height) {
    CameraUniforms u;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    u.view = camera.view();
    u.projection = camera.projection(aspect);
    u.viewProjection = u.projection * u.view;
    u.inverseProjection = glm::inverse(u.projection);
    u.inverseView = glm::inverse(u.view);
    u.viewport = glm::vec4(width, height, 1.0f / width, 1.0f / height);
    u.clip = glm::vec4(camera.nearPlane, camera.farPlane, std::tan(glm::radians(camera.fovYDegrees) * 0.5f), aspect);
    return u;
}

std::vector<PassRecord> Pipeline::plan(const FrameRequest& request, std::set<std::string>* wantedOutputs) const {
    for (const auto& name : request.outputs)
        if (!outputs_.find(name))
            throw Error("unknown buffer '" + name + "'; 'deferred-workbench list buffers' lists them");
    std::vector<PassRecord> records(passes_.size());
    std::set<std::string> needed;
    for (const auto& name : request.outputs) needed.insert(name == kFinalOutput ? resolveFinal() : name);
    // Backwards: a pass is wanted if something later (or the request) consumes it.
    std::vector<bool> wanted(passes_.size(), false);
    for (size_t i = passes_.size(); i-- > 0;) {
        const RenderPass& p = *passes_[i];
        records[i].name = p.name();
        // A pass that is switched off says so, whether or not anything wants it.
        const std::string skip = scene_ ? p.skipReason(knobs_, *scene_) : std::string();
        if (!skip.empty()) {
            records[i].reason = skip;
            continue;
        }
        bool consumed = false;
        for (const auto& o : p.outputs()) consumed = consumed || needed.count(o.name);
        if (!consumed) {
            records[i].reason = "nothing this frame consumes its outputs";
            continue;
        }
        wanted[i] = true;
        const PassIO io = p.inputs(knobs_);
        needed.insert(io.inputs.begin(), io.inputs.end());
        needed.insert(io.optionalInputs.begin(), io.optionalInputs.end());
    }
    // Forwards: a wanted pass runs if its required inputs were produced.
    std::set<std::string> produced;
    for (size_t i = 0; i < passes_.size(); ++i) {
        if (!wanted[i]) continue;
        const PassIO io = passes_[i]->inputs(knobs_);
        std::string missing;
        for (const auto& in : io.inputs)
            if (!produced.count(in)) missing = in;
        if (!missing.empty()) {
            const PublishedOutput* src = outputs_.find(missing);
            std::string why = "needs " + missing;
            if (src) {
                for (const auto& r : records)
                    if (r.name == src->pass && !r.reason.empty()) why += ", but " + r.name + " did not run (" + r.reason + ")";
            }
            records[i].reason = why;
            continue;
        }
        records[i].ran = true;
        for (const auto& o : passes_[i]->outputs()) produced.insert(o.name);
    }
    if (wantedOutputs) *wantedOutputs = needed;
    return records;
}

FrameReport Pipeline::render(const Camera& camera, const FrameRequest& request) {
    if (!shaders_ || !scene_) throw Error("Pipeline::render before setup() and setScene()");
    if (width_ <= 0) throw Error("Pipeline::render before resize()");
    FrameReport report;
    report.frameIndex = frame_;
    std::set<std::string> wanted;
    report.passes = plan(request, &wanted);
    const std::string finalName = resolveFinal();
    for (const auto& requested : request.outputs) {
        const std::string name = requested == kFinalOutput ? finalName : requested;
        const PublishedOutput* o = outputs_.find(name);
        for (const auto& r : report.passes)
            if (r.name == o->pass && !r.ran)
                throw Error("buffer '" + name + "' is not produced: pass '" + r.name + "' did not run (" + r.reason + ")");
    }

    camera_ = cameraUniforms(camera, width_, height_);
    cameraUbo_.update(0, sizeof(CameraUniforms), &camera_);
    cameraUbo_.bindBase(GL_UNIFORM_BUFFER, binding::kCameraUbo);
    outputs_.markFrameStart();
    FrameContext ctx{*scene_, gpu_, knobs_, outputs_, *shaders_, camera_, width_, height_, frame_, std::move(wanted), &timer_};

    timer_.beginFrame(frame_);
    try {
        for (size_t i = 0; i < passes_.size(); ++i) {
            if (!report.passes[i].ran) continue;
            RenderPass& p = *passes_[i];
            gl::resetPipelineState(width_, height_);
            cameraUbo_.bindBase(GL_UNIFORM_BUFFER, binding::kCameraUbo);
            glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, p.name());
            timer_.beginPass(p.name());
            try {
                p.execute(ctx);
            } catch (...) {
                glPopDebugGroup();
                throw;
            }
            timer_.endPass();
            glPopDebugGroup();
            outputs_.markProduced(p.name(), ctx.wanted);
            report.passes[i].stats = p.stats();
        }
    } catch (...) {
        // A failed frame leaves nothing half-recorded for the next one.
        timer_.abortFrame();
        gl::resetPipelineState(width_, height_);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        ++frame_;
        throw;
    }
    timer_.endFrame();
    outputs_.bindAlias(kFinalOutput, finalName);
    gl::resetPipelineState(width_, height_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ++frame_;
    return report;
}

}  // namespace dw
