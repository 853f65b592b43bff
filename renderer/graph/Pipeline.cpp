#include "renderer/graph/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <set>

#include "renderer/Error.h"
#include "renderer/gl/MemoryDomain.h"
#include "renderer/gl/MemoryLedger.h"
#include "renderer/graph/RenamedOutputs.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/scene/Scene.h"

namespace dw {

const PassRecord* FrameReport::find(const std::string& name) const {
    for (const auto& p : passes)
        if (p.name == name) return &p;
    return nullptr;
}

std::vector<std::string> FrameReport::warnings() const {
    std::vector<std::string> out;
    for (const auto& p : passes)
        if (p.ran && !p.warning.empty()) out.push_back(p.name + ": " + p.warning);
    return out;
}

namespace {

// How the passes would sample a frame under `knobs` (RenderPass::sampling,
// at a fixed size and frame): the largest scale and the first jitter.
FrameSampling sampleWith(const std::vector<std::unique_ptr<RenderPass>>& passes, const KnobRegistry& knobs) {
    FrameSampling all;
    for (const auto& p : passes) {
        const FrameSampling s = p->sampling(knobs, 1, 64, 64);
        all.scale = std::max(all.scale, s.scale);
        if (all.jitter == glm::vec2(0.0f)) all.jitter = s.jitter;
    }
    return all;
}

bool sameSampling(const FrameSampling& a, const FrameSampling& b) { return a.scale == b.scale && a.jitter == b.jitter; }

// The bool and enum knobs that change how the frame is sampled (SSAA's
// scale, TAA's jitter: aa.method, and aa.ssaa_factor once aa.method=ssaa)
// change every pass's work, so every pass reads them ("*"): each value of
// each knob from the defaults, then again with each knob found so far set
// to each of its values. Probes the passes' sampling(); needs no GL.
void markSamplingKnobs(const std::vector<std::unique_ptr<RenderPass>>& passes, const KnobRegistry& knobs,
                       std::vector<std::set<std::string>>& readers) {
    auto changes = [&](const KnobRegistry& base, size_t id) {
        const KnobSpec& s = knobs.spec(static_cast<int>(id));
        if (s.type != KnobType::Enum && s.type != KnobType::Bool) return false;
        const FrameSampling before = sampleWith(passes, base);
        KnobRegistry probe = base;
        for (double v = s.minValue; v <= s.maxValue; v += 1.0) {
            probe.set(static_cast<int>(id), v);
            if (!sameSampling(sampleWith(passes, probe), before)) return true;
        }
        return false;
    };
    std::vector<size_t> found;
    for (size_t id = 0; id < knobs.size(); ++id)
        if (changes(knobs, id)) found.push_back(id);
    for (size_t f : std::vector<size_t>(found)) {
        const KnobSpec& s = knobs.spec(static_cast<int>(f));
        for (double v = s.minValue; v <= s.maxValue; v += 1.0) {
            KnobRegistry base = knobs;
            base.set(static_cast<int>(f), v);
            for (size_t id = 0; id < knobs.size(); ++id)
                if (std::find(found.begin(), found.end(), id) == found.end() && changes(base, id)) found.push_back(id);
        }
    }
    for (size_t id : found) readers[id].insert("*");
    sampleWith(passes, knobs);  // leave each pass as the current knobs have it
}

}  // namespace

Pipeline::Pipeline(KnobRegistry& knobs) : knobs_(knobs) {
    // Built-in passes first, then any registered from outside; within a stage
    // in registration order (seed 002 section 6 for the built-in ones).
    std::vector<PassEntry> entries = builtinPasses();
    for (const auto& e : PassCatalog::extra().entries()) entries.push_back(e);
    std::stable_sort(entries.begin(), entries.end(),
                     [](const PassEntry& a, const PassEntry& b) { return a.stage < b.stage; });
    // Which pass reads which knob: those it declares, and those it looks up
    // while it is made and connected (KnobRegistry::logLookups).
    std::vector<std::vector<int>> lookups;
    for (const auto& e : entries) {
        std::vector<int> log;
        const size_t declared = knobs.size();
        knobs.logLookups(&log);
        try {
            passes_.push_back(e.make(knobs));
        } catch (...) {
            knobs.logLookups(nullptr);
            throw;
        }
        knobs.logLookups(nullptr);
        for (size_t id = declared; id < knobs.size(); ++id) log.push_back(static_cast<int>(id));
        lookups.push_back(std::move(log));
        stages_.push_back(e.stage);
    }
    for (size_t i = 0; i < passes_.size(); ++i) {
        knobs.logLookups(&lookups[i]);
        try {
            passes_[i]->connect(knobs);
        } catch (...) {
            knobs.logLookups(nullptr);
            throw;
        }
        knobs.logLookups(nullptr);
    }
    knobReaders_.assign(knobs.size(), {});
    for (size_t i = 0; i < passes_.size(); ++i)
        for (int id : lookups[i])
            if (id >= 0 && static_cast<size_t>(id) < knobReaders_.size()) knobReaders_[static_cast<size_t>(id)].insert(passes_[i]->name());
    std::set<std::string> names;
    for (const auto& p : passes_) {
        if (!names.insert(p->name()).second) throw Error(std::string("two passes are named '") + p->name() + "'");
        for (const auto& o : p->outputs()) outputs_.declare(p->name(), o);
    }
    if (std::count(stages_.begin(), stages_.end(), PassStage::Tonemap) != 1)
        throw Error("the pipeline needs exactly one pass of stage Tonemap (the head of the post chain)");
    for (size_t i = 0; i < passes_.size(); ++i)
        if ((stages_[i] == PassStage::Tonemap || stages_[i] == PassStage::Post) && passes_[i]->outputs().empty())
            throw Error(std::string("post pass '") + passes_[i]->name() + "' declares no output image");
    outputs_.declare("pipeline", {kFinalOutput, OutputKind::Color,
                                  "the display image: the end of the post chain (tonemap.result, then each post pass that ran)"});
    depthMode_ = knobs.requireEnum("depth.mode");
    knobReaders_[static_cast<size_t>(depthMode_.id)].insert("*");  // the camera every pass uses
    markSamplingKnobs(passes_, knobs, knobReaders_);
    normalEncoding_ = knobs.requireEnum("gbuffer.normal_encoding");
    octahedral_[0] = knobs.choiceIndex(normalEncoding_, "oct16");
    octahedral_[1] = knobs.choiceIndex(normalEncoding_, "oct8");
    knobReaders_[static_cast<size_t>(normalEncoding_.id)].insert("*");  // every reader of gbuffer.normal decodes by it
}

const std::set<std::string>& Pipeline::knobReaders(int knob) const {
    static const std::set<std::string> none;
    return knob >= 0 && static_cast<size_t>(knob) < knobReaders_.size() ? knobReaders_[static_cast<size_t>(knob)] : none;
}

Pipeline::~Pipeline() = default;

PassStage Pipeline::stageOf(const RenderPass& pass) const {
    for (size_t i = 0; i < passes_.size(); ++i)
        if (passes_[i].get() == &pass) return stages_[i];
    throw Error(std::string("pass '") + pass.name() + "' is not in this pipeline");
}

RenderPass* Pipeline::findPass(const std::string& name) const {
    for (const auto& p : passes_)
        if (name == p->name()) return p.get();
    return nullptr;
}

void Pipeline::setup(gl::ShaderLibrary& shaders) {
    shaders_ = &shaders;
    // What this pipeline allocates is its own ledger domain (bench's peak per configuration).
    gl::resetDomainPeak(this);
    gl::MemoryDomain domain(this);
    for (auto& p : passes_) {
        // What a pass allocates for itself is counted under its name unless
        // it names a finer owner (gl/MemoryLedger.h).
        gl::MemoryOwner owner(std::string("pass ") + p->name());
        p->setup(shaders);
    }
    gl::MemoryOwner owner("camera uniforms");
    cameraUbo_.create();
}

void Pipeline::setScene(const Scene& scene) {
    // Build the new GPU copy aside, so a failure keeps the previous scene.
    gl::MemoryDomain domain(this);
    GpuScene next;
    next.setGpuPosing(gpuPosing_);
    next.upload(scene, shaders_);
    gpu_ = std::move(next);
    scene_ = &scene;
}

void Pipeline::bindCamera(const Camera& camera) {
    camera_ = cameraUniforms(camera, width_, height_, knobs_.get(depthMode_) == 0 ? DepthMode::Reversed : DepthMode::Conventional);
    camera_.gbuffer.x = normalEncodingUniform();
    cameraUbo_.upload(camera_, binding::CAMERA_UBO);  // the gpu::CameraBlock part
    gpu_.setDrawOrigin(camera_.origin);
}

void Pipeline::resize(int width, int height) {
    if (width <= 0 || height <= 0) throw Error("render size must be positive");
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    gl::MemoryDomain domain(this);
    // Managed outputs follow the size at the next frame; imported ones now.
    for (auto& p : passes_) {
        gl::MemoryOwner owner(std::string("pass ") + p->name());
        p->resize(width, height, outputs_);
    }
}

CameraUniforms Pipeline::cameraUniforms(const Camera& camera, int width, int height, DepthMode depthMode,
                                        glm::vec2 jitter) {
    CameraUniforms u;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const DepthConvention convention(depthMode);
    // In double precision, rounded once: the inverse of a projection with
    // near 1e-5 and far 1e7 loses most of its digits when inverted in float.
    // Camera-relative: the view is a rotation; world positions reach the GPU
    // minus the camera's position (CameraUniforms::origin).
    const glm::dvec3 eye(camera.position);
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0.0), glm::dvec3(camera.target) - eye, glm::dvec3(camera.up));
    // The jitter moves clip space by 2 * jitter / size in x and y (NDC), for
    // any projection: a translation applied after it.
    glm::dmat4 shift(1.0);
    shift[3][0] = 2.0 * jitter.x / width;
    shift[3][1] = 2.0 * jitter.y / height;
    const glm::dmat4 projection = shift * convention.perspective(glm::radians(static_cast<double>(camera.fovYDegrees)),
                                                         static_cast<double>(width) / height, camera.nearPlane,
                                                         camera.farPlane);
    u.view = glm::mat4(view);
    u.projection = glm::mat4(projection);
    u.viewProjection = glm::mat4(projection * view);
    u.inverseProjection = glm::mat4(glm::inverse(projection));
    u.inverseView = glm::mat4(glm::inverse(view));
    u.depth = convention.uniform();
    u.origin = eye;
    u.viewport = glm::vec4(width, height, 1.0f / width, 1.0f / height);
    u.clip = glm::vec4(camera.nearPlane, camera.farPlane, std::tan(glm::radians(camera.fovYDegrees) * 0.5f), aspect);
    return u;
}

float Pipeline::normalEncodingUniform() const {
    const int e = knobs_.get(normalEncoding_);
    return e == octahedral_[0] || e == octahedral_[1] ? 1.0f : 0.0f;
}

std::string Pipeline::resolveFinal() const { return makePlan({{}}).finalName; }

PassIO Pipeline::resolvedInputs(size_t i, const Plan& plan) const {
    PassIO io = passes_[i]->inputs(knobs_);
    for (auto* list : {&io.inputs, &io.optionalInputs, &io.modifies})
        for (auto& name : *list)
            if (name == kCurrentImage) name = plan.image[i];
    return io;
}

std::vector<size_t> Pipeline::orderPasses(const std::vector<PassIO>& io) const {
    // Kahn's algorithm over the read / write / modify edges; among the passes
    // that are free to go, the one registered first (stage, then registration).
    const size_t n = passes_.size();
    std::map<std::string, size_t> producer;
    for (size_t i = 0; i < n; ++i)
        for (const auto& o : passes_[i]->outputs()) producer[o.name] = i;
    std::vector<std::set<size_t>> next(n);
    auto edge = [&](size_t from, size_t to) {
        if (from != to) next[from].insert(to);
    };
    for (size_t i = 0; i < n; ++i) {
        for (const auto* list : {&io[i].inputs, &io[i].optionalInputs, &io[i].modifies})
            for (const auto& name : *list)
                if (auto p = producer.find(name); p != producer.end()) edge(p->second, i);
        // A pass that adds into a resource runs before everyone else who reads it.
        for (const auto& name : io[i].modifies)
            for (size_t j = 0; j < n; ++j) {
                const auto& r = io[j];
                const bool reads = std::count(r.inputs.begin(), r.inputs.end(), name) ||
                                   std::count(r.optionalInputs.begin(), r.optionalInputs.end(), name);
                const bool modifies = std::count(r.modifies.begin(), r.modifies.end(), name);
                if (reads && !modifies) edge(i, j);
            }
    }
    std::vector<int> incoming(n, 0);
    for (size_t i = 0; i < n; ++i)
        for (size_t j : next[i]) ++incoming[j];
    std::set<size_t> ready;
    for (size_t i = 0; i < n; ++i)
        if (incoming[i] == 0) ready.insert(i);
    std::vector<size_t> order;
    while (!ready.empty()) {
        const size_t i = *ready.begin();
        ready.erase(ready.begin());
        order.push_back(i);
        for (size_t j : next[i])
            if (--incoming[j] == 0) ready.insert(j);
    }
    if (order.size() != n) {
        std::string cycle;
        for (size_t i = 0; i < n; ++i)
            if (incoming[i] > 0) cycle += (cycle.empty() ? "" : ", ") + std::string(passes_[i]->name());
        throw Error("the passes' inputs and outputs form a cycle among: " + cycle);
    }
    return order;
}

Pipeline::Plan Pipeline::makePlan(const FrameRequest& request) const {
    for (const auto& name : request.outputs)
        if (!outputs_.find(name))
            throw Error(unknownBufferMessage(name) + "; 'deferred-workbench list buffers' lists them");
    const size_t n = passes_.size();
    Plan plan;
    plan.records.resize(n);
    plan.image.resize(n);
    // The post chain: the tone mapper's image, then every Post pass that is
    // switched on takes the image so far and makes the next.
    std::vector<std::string> skip(n);
    for (size_t i = 0; i < n; ++i) {
        plan.records[i].name = passes_[i]->name();
        skip[i] = scene_ ? passes_[i]->skipReason(knobs_, *scene_) : std::string();
        if (skip[i].empty() && scene_ && viewKnown_) skip[i] = passes_[i]->viewSkipReason(knobs_, *scene_, camera_);
    }
    for (size_t i = 0; i < n; ++i) {
        if (stages_[i] == PassStage::Tonemap) plan.finalName = passes_[i]->outputs().front().name;
    }
    for (size_t i = 0; i < n; ++i) {
        if (stages_[i] != PassStage::Post) continue;
        plan.image[i] = plan.finalName;
        if (skip[i].empty()) plan.finalName = passes_[i]->outputs().front().name;
    }
    std::vector<PassIO> io(n);
    for (size_t i = 0; i < n; ++i) io[i] = resolvedInputs(i, plan);
    plan.order = orderPasses(io);

    std::set<std::string> needed;
    for (const auto& name : request.outputs) needed.insert(name == kFinalOutput ? plan.finalName : name);
    // Backwards: a pass is wanted if something later (or the request)
    // consumes what it writes or adds into.
    std::vector<bool> wanted(n, false);
    for (auto it = plan.order.rbegin(); it != plan.order.rend(); ++it) {
        const size_t i = *it;
        // A pass that is switched off says so, whether or not anything wants it.
        if (!skip[i].empty()) {
            plan.records[i].reason = skip[i];
            continue;
        }
        bool consumed = false;
        for (const auto& o : passes_[i]->outputs()) consumed = consumed || needed.count(o.name);
        for (const auto& m : io[i].modifies) consumed = consumed || needed.count(m);
        if (!consumed) {
            plan.records[i].reason = "nothing this frame consumes its outputs";
            continue;
        }
        wanted[i] = true;
        needed.insert(io[i].inputs.begin(), io[i].inputs.end());
        needed.insert(io[i].optionalInputs.begin(), io[i].optionalInputs.end());
        needed.insert(io[i].modifies.begin(), io[i].modifies.end());
    }
    // Forwards: a wanted pass runs if what it needs was produced.
    std::set<std::string> produced;
    for (const size_t i : plan.order) {
        if (!wanted[i]) continue;
        std::string missing;
        for (const auto* list : {&io[i].inputs, &io[i].modifies})
            for (const auto& in : *list)
                if (!produced.count(in)) missing = in;
        if (!missing.empty()) {
            const PublishedOutput* src = outputs_.find(missing);
            std::string why = "needs " + missing;
            if (src)
                for (const auto& r : plan.records)
                    if (r.name == src->pass && !r.reason.empty()) why += ", but " + r.name + " did not run (" + r.reason + ")";
            plan.records[i].reason = why;
            continue;
        }
        plan.records[i].ran = true;
        for (const auto& o : passes_[i]->outputs()) produced.insert(o.name);
    }
    plan.wanted = std::move(needed);
    return plan;
}

std::vector<PassRecord> Pipeline::plan(const FrameRequest& request, std::set<std::string>* wantedOutputs) const {
    Plan p = makePlan(request);
    std::vector<PassRecord> records;
    for (size_t i : p.order) records.push_back(p.records[i]);
    if (wantedOutputs) *wantedOutputs = p.wanted;
    return records;
}

std::vector<PassInfo> Pipeline::passList() const {
    Plan p = makePlan({{}});
    std::vector<PassInfo> list;
    for (size_t i : p.order) {
        const PassIO io = resolvedInputs(i, p);
        list.push_back({passes_[i]->name(), stages_[i], io.inputs, io.optionalInputs, io.modifies, passes_[i]->outputs()});
    }
    return list;
}

void Pipeline::allocateResources(const Plan& plan) {
    // Managed outputs exist while their writer runs (and, for on-demand ones,
    // something asks for them); everything else is freed.
    for (size_t i = 0; i < passes_.size(); ++i) {
        const RenderPass& p = *passes_[i];
        if (plan.records[i].ran) {
            pool_.acquireOutputs(p, knobs_, renderWidth(), renderHeight(), outputs_, &plan.wanted);
            continue;
        }
        for (const auto& o : p.outputs()) {
            if (!o.resource.managed() && o.viewOf.empty()) continue;
            pool_.release(o.name);
            outputs_.bindResource(o.name, nullptr, nullptr, {}, 0);
        }
    }
}

std::int64_t Pipeline::declaredBytes(size_t i, const Plan& plan) const {
    const PassIO io = resolvedInputs(i, plan);
    std::set<std::string> names(io.inputs.begin(), io.inputs.end());
    names.insert(io.optionalInputs.begin(), io.optionalInputs.end());
    names.insert(io.modifies.begin(), io.modifies.end());
    for (const auto& o : passes_[i]->outputs())
        if (o.viewOf.empty()) names.insert(o.name);
    std::int64_t bytes = 0;
    for (const auto& name : names) {
        const PublishedOutput* o = outputs_.find(name);
        if (!o || !o->allocated() || !o->decl.viewOf.empty()) continue;
        bytes += static_cast<std::int64_t>(resourceBytes(o->desc, renderWidth(), renderHeight()));
    }
    return bytes;
}

void Pipeline::chooseSampling() {
    scale_ = 1;
    jitter_ = glm::vec2(0.0f);
    for (auto& p : passes_) {
        const FrameSampling s = p->sampling(knobs_, frame_, width_, height_);
        scale_ = std::max(scale_, s.scale);
        if (jitter_ == glm::vec2(0.0f)) jitter_ = s.jitter;
    }
}

FrameReport Pipeline::render(const Camera& camera, const FrameRequest& request) {
    if (!shaders_ || !scene_) throw Error("Pipeline::render before setup() and setScene()");
    if (width_ <= 0) throw Error("Pipeline::render before resize()");
    gl::MemoryDomain domain(this);
    FrameReport report;
    report.frameIndex = frame_;
    // How the frame is sampled (SSAA's scale, TAA's jitter), then the camera:
    // a pass may skip this frame for what is in view.
    chooseSampling();
    camera_ = cameraUniforms(camera, renderWidth(), renderHeight(),
                             knobs_.get(depthMode_) == 0 ? DepthMode::Reversed : DepthMode::Conventional, jitter_);
    camera_.gbuffer.x = normalEncodingUniform();
    viewKnown_ = true;
    Plan plan = makePlan(request);
    for (size_t i : plan.order) report.passes.push_back(plan.records[i]);
    for (const auto& requested : request.outputs) {
        const std::string name = requested == kFinalOutput ? plan.finalName : requested;
        const PublishedOutput* o = outputs_.find(name);
        for (const auto& r : report.passes)
            if (r.name == o->pass && !r.ran)
                throw Error("buffer '" + name + "' is not produced: pass '" + r.name + "' did not run (" + r.reason + ")");
    }

    cameraUbo_.upload(camera_, binding::CAMERA_UBO);  // the gpu::CameraBlock part
    gpu_.setDrawOrigin(camera_.origin);
    allocateResources(plan);
    outputs_.markFrameStart();
    FrameContext ctx{*scene_, gpu_, knobs_, outputs_, *shaders_, camera_, renderWidth(), renderHeight(), frame_, plan.wanted, &timer_};
    for (const auto& r : request.outputs) ctx.requested.insert(r == kFinalOutput ? plan.finalName : r);

    timer_.beginFrame(frame_);
    try {
        for (size_t i : plan.order) {
            if (!plan.records[i].ran) continue;
            RenderPass& p = *passes_[i];
            ctx.image = plan.image[i];
            gl::resetPipelineState(renderWidth(), renderHeight());
            cameraUbo_.bind(binding::CAMERA_UBO);
            glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, p.name());
            timer_.beginPass(p.name());
            try {
                gl::MemoryOwner owner(std::string("pass ") + p.name());
                p.execute(ctx);
            } catch (...) {
                glPopDebugGroup();
                throw;
            }
            if (timer_.counting()) timer_.setPassBytes(declaredBytes(i, plan));
            timer_.endPass();
            glPopDebugGroup();
            outputs_.markProduced(p.name(), ctx.wanted);
        }
        // Each pass's line once the whole frame ran: a service one pass
        // offers can do its work inside a later pass (the shadow maps a
        // lighting strategy renders light by light with shadows.reuse_map).
        size_t slot = 0;
        for (size_t i : plan.order) {
            const size_t reportIndex = slot++;
            if (!plan.records[i].ran) continue;
            report.passes[reportIndex].stats = passes_[i]->stats();
            report.passes[reportIndex].warning = passes_[i]->frameWarning();
        }
    } catch (...) {
        // A failed frame leaves nothing half-recorded for the next one.
        timer_.abortFrame();
        gl::resetPipelineState(renderWidth(), renderHeight());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        ++frame_;
        throw;
    }
    timer_.endFrame();
    outputs_.bindAlias(kFinalOutput, plan.finalName);
    gl::resetPipelineState(renderWidth(), renderHeight());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ++frame_;
    return report;
}

}  // namespace dw
