#include "renderer/RenderSession.h"

#include <fstream>
#include <memory>

#include "renderer/Error.h"
#include "renderer/graph/RenamedOutputs.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/passes/ReferencePass.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/scene/ClipChoice.h"
#include "renderer/scene/SceneLoader.h"
#include "renderer/scene/ScenePose.h"

namespace dw {

RenderSession::RenderSession(const std::filesystem::path& shaderRoot)
    : info_(gl::requireGl45()), shaders_(shaderRoot), pipeline_(knobs_) {
    gl::installDebugOutput();
    pipeline_.setup(shaders_);
    view_.setup(shaders_);
}

void RenderSession::loadScene(const std::string& spec, const RunConfig& run) { setScene(dw::loadScene(spec), run); }

void RenderSession::setScene(Scene scene, const RunConfig& run) {
    // Work the knob values out on a copy and upload next: if either throws,
    // the previous scene, knobs and camera stay in place.
    KnobRegistry next = knobs_;
    run.applyKnobs(next, scene);
    auto uploaded = std::make_unique<Scene>(std::move(scene));
    chooseClip(uploaded->animation, run.animation);
    poseScene(*uploaded, run.sceneTime);
    pipeline_.setScene(*uploaded);
    sceneTime_ = run.sceneTime;
    scene_ = std::move(uploaded);
    camera_ = run.camera(*scene_);
    knobs_.copyValues(next);
}

void RenderSession::poseAtSceneTime() {
    if (poseScene(*scene_, sceneTime_)) pipeline_.updatePose(*scene_);
}

FrameReport RenderSession::render(const FrameRequest& request) {
    animateFlameParticles(*scene_, pipeline_.frameIndex());
    poseAtSceneTime();
    return pipeline_.render(camera_, request);
}

FloatImage RenderSession::readRaw(const std::string& output, ViewSelection selection) const {
    const PublishedOutput* o = pipeline_.outputs().find(output);
    if (!o) throw Error(unknownBufferMessage(output));
    return readOutputRaw(*o, selection);
}

FloatImage RenderSession::readDisplay(const std::string& output, BufferViewSettings settings) {
    const PublishedOutput* o = pipeline_.outputs().find(output);
    if (!o) throw Error(unknownBufferMessage(output));
    if (isDisplayReady(*o)) return readOutputRaw(*o);
    settings.nearPlane = camera_.nearPlane;
    settings.farPlane = camera_.farPlane;
    settings.reversedDepth = pipeline_.lastCamera().depth.x > 0.5f;
    return readRgba8(view_.render(*o, settings));
}

void RenderSession::writeKnobValues(const std::string& path) const {
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw FileError(path, "cannot write the knob values");
    out << "# scene " << scene_->source << "\n";
    for (size_t i = 0; i < knobs_.size(); ++i)
        out << knobs_.spec(static_cast<int>(i)).name << "=" << knobs_.format(static_cast<int>(i)) << "\n";
    if (!out.flush()) throw FileError(path, "writing the knob values failed");
}

void RenderSession::writeOutput(const std::string& output, const std::string& path, const BufferViewSettings& settings) {
    const PublishedOutput* o = pipeline_.outputs().find(output);
    if (!o) throw Error(unknownBufferMessage(output));
    if (isFloatFormat(path)) writeImage(path, readRaw(output, settings.selection()), rawChannelNames(*o));
    else writeImage(path, readDisplay(output, settings));
}

void RenderSession::showReference(const reference::ReferenceImages* images, const std::string& staleReason) {
    auto* pass = pipeline_.pass<ReferencePass>();
    if (!pass) return;
    if (images) {
        auto shown = std::make_shared<ReferencePass::Images>();
        shown->lbuffer = images->lbuffer;
        shown->final = images->final;
        shown->ao = images->ao;
        shown->sppError = images->sppError;
        shown->describe = "CPU reference (" + std::to_string(images->stats.primaryRays) + " primary rays)";
        pass->setReference(std::move(shown));
    } else if (pass->hasReference()) {
        pass->setReference(nullptr, staleReason);
    }
}

bool RenderSession::isReferenceOutput(const std::string& buffer) const {
    const PublishedOutput* o = pipeline_.outputs().find(buffer);
    return o && o->pass == "reference";
}

}  // namespace dw
