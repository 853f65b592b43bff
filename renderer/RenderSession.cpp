#include "renderer/RenderSession.h"

#include "renderer/Error.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

RenderSession::RenderSession(const std::filesystem::path& shaderRoot)
    : info_(gl::requireGl45()), shaders_(shaderRoot), pipeline_(knobs_) {
    gl::installDebugOutput();
    pipeline_.setup(shaders_);
    view_.setup(shaders_);
}

void RenderSession::loadScene(const std::string& spec) { setScene(dw::loadScene(spec)); }

void RenderSession::setScene(Scene scene) {
    // Check the scene's knob settings and upload first: if either throws, the
    // previous scene and knob values stay in place.
    KnobRegistry check = knobs_;
    for (const auto& [name, value] : scene.settings) {
        try {
            check.setFromString(name, value);
        } catch (const Error& e) {
            throw FileError(scene.source, std::string("settings: ") + e.what());
        }
    }
    auto next = std::make_unique<Scene>(std::move(scene));
    pipeline_.setScene(*next);
    scene_ = std::move(next);
    camera_ = scene_->camera;
    for (const auto& [name, value] : scene_->settings) knobs_.setFromString(name, value);
}

FloatImage RenderSession::readRaw(const std::string& output, ViewSelection selection) const {
    const PublishedOutput* o = pipeline_.outputs().find(output);
    if (!o) throw Error("unknown buffer '" + output + "'");
    return readOutputRaw(*o, selection);
}

FloatImage RenderSession::readDisplay(const std::string& output, BufferViewSettings settings) {
    const PublishedOutput* o = pipeline_.outputs().find(output);
    if (!o) throw Error("unknown buffer '" + output + "'");
    if (isDisplayReady(*o)) return readOutputRaw(*o);
    settings.nearPlane = camera_.nearPlane;
    settings.farPlane = camera_.farPlane;
    return readRgba8(view_.render(*o, settings));
}

void RenderSession::writeOutput(const std::string& output, const std::string& path, const BufferViewSettings& settings) {
    const PublishedOutput* o = pipeline_.outputs().find(output);
    if (!o) throw Error("unknown buffer '" + output + "'");
    if (isFloatFormat(path)) writeImage(path, readRaw(output, settings.selection()), rawChannelNames(*o));
    else writeImage(path, readDisplay(output, settings));
}

}  // namespace dw
