#include "ui/ViewportComposer.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <type_traits>

#include "renderer/ao/AovCostEstimate.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/io/ImageHistogram.h"
#include "renderer/lighting/LightVolume.h"
#include "renderer/metrics/ImageComparison.h"
#include "renderer/passes/ReferencePass.h"
#include "renderer/scene/FlameParticles.h"

namespace dw::ui {

ViewportComposer::ViewportComposer(RenderSession& session) : session_(session) {
    sideView_.setup(session.shaders());
    forward_.setup(session.shaders());
    overlay_.setup(session.shaders());
    nearest_ = gl::Sampler::create(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, "workbench pixel zoom");
}

glm::ivec2 ViewportComposer::targetSize(const UiState& state) {
    if (state.wantedSize.x <= 0) return state.renderSize;
    const float scale = state.viewport.scale();
    return {std::max(16, static_cast<int>(std::lround(state.wantedSize.x * scale))),
            std::max(16, static_cast<int>(std::lround(state.wantedSize.y * scale)))};
}

void ViewportComposer::render(UiState& state) {
    followViewport(state);
    stepBackgroundWork(state);
    renderOnChange(state);
}

void ViewportComposer::followViewport(UiState& state) {
    // The render size: the viewport panel's, times the resolution scale.
    if (state.wantedSize.x > 0) {
        const glm::ivec2 target = targetSize(state);
        if (target != state.renderSize) {
            session_.resize(target.x, target.y);
            state.renderSize = target;
        }
    }
    state.animator.update(session_.mutableScene(), state.frame);
    if (state.timeline.advance(session_)) state.forceRender = true;
}

void ViewportComposer::stepBackgroundWork(UiState& state) {
    // A change being measured: one of its frames (the knob values of its
    // side, on the stepping runner), then the view renders its own after it
    // (one measured frame a UI frame, so the window stays responsive).
    measuring_ = false;
    if (state.measure.active()) {
        if (state.viewport.mode != DisplayMode::Deferred) {
            state.measure.cancel(session_.knobs(), "cancelled: a forward view runs no deferred pass");
        } else {
            measuring_ = true;
            state.measure.step(session_);
            state.forceRender = true;
        }
    }
    // A quick sweep's frame first; the view renders again after it.
    if (state.sweep.running() && state.viewport.mode == DisplayMode::Deferred && !measuring_) {
        state.sweep.step(session_);
        state.forceRender = true;
    } else if (state.attribution.running() && state.viewport.mode == DisplayMode::Deferred && !measuring_) {
        state.attribution.step(session_);
        state.forceRender = true;
    } else if (state.fitBudget.running() && state.viewport.mode == DisplayMode::Deferred && !measuring_) {
        state.fitBudget.step(session_);
        state.forceRender = true;
    }
    // File > Save record's measured frame, of the state saved (it puts the current one back).
    if (state.recordRun.running() && !measuring_) state.recordRun.step(state, session_);
}

void ViewportComposer::renderOnChange(UiState& state) {
    Pipeline& pipeline = session_.pipeline();
    const bool measuring = measuring_;
    if (state.ab.pinRequest) {
        state.ab.pinRequest = false;
        pin(state);
    }
    // Render only when something the images depend on changed, unless
    // timings are being captured (every frame then); the A/B view renders
    // until each side has its frame times.
    const std::string signature = frameSignature(state);
    const bool changed = signature != lastSignature_;
    const bool ab = abActive(state);
    if (changed) {
        abFramesA_.clear();
        abFramesB_.clear();
        abRenders_ = 0;
    }
    // Counted by attempts, not by frames that worked: a preset that does not
    // render (or a failing frame) must not keep the window rendering.
    const bool abMore = ab && !measuring && abRenders_ < kAbFrames;
    const bool needed = state.timingCapture || state.animator.running() || state.timeline.running() || state.forceRender ||
                        changed || abMore;
    state.forceRender = false;
    // The probe's values describe the image they were read from: another
    // image (a scene opened, the camera moved) with the probe neither
    // hovered nor pinned leaves nothing to show, not the old pixel's values.
    if (changed && !state.probe.hovering && !state.probe.pinned) state.probe = ProbeState{};
    if (needed) {
        lastSignature_ = signature;
        if (ab) ++abRenders_;
        renderImages(state);
        ++state.framesRendered;
        if (ab && (signature != composedSignature_ || !state.ab.ready)) {
            composedSignature_ = signature;
            composeAb(state);
        }
        // The first frame of another scene or render size starts the statistics over.
        const std::string config = session_.scene().source + "|" + std::to_string(state.renderSize.x) + "x" +
                                   std::to_string(state.renderSize.y);
        if (config != lastConfig_) {
            lastConfig_ = config;
            state.configSince = state.report.frameIndex;
        }
        adjustAutoScale(state);
    } else {
        // Nothing new to render, but a histogram asked for since the last
        // frame is taken from the frame on show, not left waiting for the next.
        refreshHistograms(state);
    }
    // The timer results come back a few frames late; an idle window
    // renders no later frame to pick them up, so poll here every UI frame
    // (it never waits) until the latest frame's results are in.
    pipeline.timer().collect(false);
    if (ab) abTimes(state);
    else state.ab.ready = false;
    state.timingsPending =
        pipeline.timer().pendingFrames() > 0 || state.measure.active() || abMore || state.recordRun.running();
    if (state.probe.hovering || state.probe.pinned) {
        state.probe.result = probePixel(pipeline, state.probe.pixel.x, state.probe.pixel.y);
        probeLights(state);
    }
}

// The lights whose volumes contain the probed surface point.
void ViewportComposer::probeLights(UiState& state) {
    ProbeState& p = state.probe;
    p.lights.clear();
    p.lightLines.clear();
    p.directionalLights = 0;
    if (!p.result.inside || p.result.surface.background) return;
    const Scene& scene = session_.scene();
    const double threshold = session_.knobs().value(*session_.knobs().find("lighting.threshold"));
    const glm::vec3 at = p.result.surface.worldPosition;
    p.lights = lightsCovering(scene.lights, at, threshold,
                              static_cast<int>(session_.knobs().value(*session_.knobs().find("lighting.volume_subdivisions"))));
    for (const Light& l : scene.lights) p.directionalLights += l.enabled && l.type == LightType::Directional;
    for (int i : p.lights) {
        const Light& l = scene.lights[static_cast<size_t>(i)];
        char line[200];
        std::snprintf(line, sizeof(line), "#%d %s (%s), %.3g from it, volume radius %.3g", i, l.name.c_str(), toString(l.type),
                      static_cast<double>(glm::distance(l.position, at)), computeLightVolume(l, threshold).radius);
        p.lightLines.push_back(line);
    }
}

// Everything a frame's images depend on that the window can change, as bytes.
std::string ViewportComposer::frameSignature(const UiState& state) const {
    std::string s;
    auto put = [&s](const auto& v) {
        static_assert(std::is_arithmetic_v<std::decay_t<decltype(v)>>);
        s.append(reinterpret_cast<const char*>(&v), sizeof(v));
    };
    auto vec = [&](const glm::vec3& v) { put(v.x), put(v.y), put(v.z); };
    auto text = [&](const std::string& t) { put(t.size()), s.append(t); };
    auto view = [&](const BufferViewSettings& b) {
        put(static_cast<int>(b.mapping)), put(static_cast<int>(b.channel)), put(b.autoRange), put(b.rangeMin), put(b.rangeMax);
        put(b.exposure), put(b.layer), put(b.sample);
    };
    const Camera& c = session_.camera();
    vec(c.position), vec(c.target), vec(c.up), put(c.fovYDegrees), put(c.nearPlane), put(c.farPlane);
    // The knobs by value, not by generation(): the A/B view's preset side
    // sets knobs and puts them back every frame it renders.
    const KnobRegistry& knobs = session_.knobs();
    for (size_t i = 0; i < knobs.size(); ++i) put(knobs.value(static_cast<int>(i)));
    const AbView& ab = state.ab;
    put(ab.enabled), put(static_cast<int>(ab.source)), put(static_cast<int>(ab.display)), text(ab.preset), put(ab.generation);
    const Scene& scene = session_.scene();
    put(reinterpret_cast<std::uintptr_t>(&scene)), text(scene.source), vec(scene.ambient), vec(scene.background);
    for (const Light& l : scene.lights) {
        put(static_cast<int>(l.type)), vec(l.position), vec(l.direction), put(l.cutoffDegrees), put(l.exponent);
        put(static_cast<int>(l.falloff)), put(l.innerConeDegrees);
        vec(l.intensity), put(l.attenuation.constant), put(l.attenuation.linear), put(l.attenuation.quadratic);
        put(l.castShadows), put(l.enabled);
    }
    text(state.viewport.output), put(static_cast<int>(state.viewport.mode)), view(state.viewport.settingsOr());
    const OverlaySettings& o = state.viewport.overlay;
    put(o.lightVolumes), put(static_cast<int>(state.viewport.volumes)), put(o.selectedLight), put(o.axes);
    if (o.lightVolumes && state.viewport.volumes == VolumeFilter::AtProbe)
        for (int i : state.probe.lights) put(i);
    put(state.panels.sideView), text(state.side.output), view(state.side.settingsOr());
    put(state.renderSize.x), put(state.renderSize.y), put(state.shaderGeneration);
    return s;
}

// Auto resolution: a step towards the frame-time target every few frames
// rendered, from the newest GPU frame times; frozen while timings are captured.
void ViewportComposer::adjustAutoScale(UiState& state) {
    ViewportView& v = state.viewport;
    // Nor while a sweep or an attribution renders its own frames: their times
    // are not the view's, and a new size would stop them.
    if (v.resolution != ResolutionScale::Auto || state.timingCapture || state.measure.active() || state.holdView ||
        state.sweep.running() || state.attribution.running() || state.fitBudget.running() ||
        state.framesRendered % 4 != 0)
        return;
    const PassTimer::Series* total = session_.pipeline().timer().find(PassTimer::kFrameSeries);
    if (!total || total->samples.size() < 2) return;
    std::vector<float> newest;
    for (auto it = total->samples.rbegin(); it != total->samples.rend() && newest.size() < 3; ++it) newest.push_back(it->gpuMs);
    v.autoScale = nextAutoScale(v.autoScale, computeStats(newest).median, v.frameTargetMs);
}

void ViewportComposer::renderImages(UiState& state) {
    Pipeline& pipeline = session_.pipeline();

    // The final image always; the viewed buffers when they can be produced.
    FrameRequest request;
    std::string viewportWhy, sideWhy;
    const bool deferred = state.viewport.mode == DisplayMode::Deferred;
    auto tryAdd = [&](const std::string& name, std::string& why) {
        if (name == "final" || name.empty()) return;
        FrameRequest probe{{"final", name}};
        try {
            for (const auto& r : pipeline.plan(probe))
                if (r.name == pipeline.outputs().find(name)->pass && !r.ran) {
                    why = name + " is not produced: pass '" + r.name + "' did not run (" + r.reason + ")";
                    return;
                }
            request.outputs.push_back(name);
        } catch (const std::exception& e) {
            why = e.what();
        }
    };
    if (deferred) tryAdd(state.viewport.output, viewportWhy);
    const bool ab = abActive(state);
    std::string referenceWhy;
    if (ab) {
        if (const ReferencePass* r = pipeline.pass<ReferencePass>(); r && r->hasReference()) tryAdd("reference.final", referenceWhy);
        // B first, so the pipeline's outputs (the probe's, the histograms') are A's.
        if (state.ab.source == AbSource::Preset) renderPresetSide(state);
    }
    if (state.panels.sideView) tryAdd(state.side.output, sideWhy);
    state.flameFrame = state.heldFlameFrame.value_or(pipeline.frameIndex());
    animateFlameParticles(session_.mutableScene(), state.flameFrame);
    // The forward preview modes run no deferred pass at all.
    if (deferred) {
        state.report = pipeline.render(session_.camera(), request);
        logFrameWarnings(state);
        if (ab) {
            abFramesA_.insert(state.report.frameIndex);
            abA_ = session_.readRaw("final");
            abReference_ = FloatImage{};
            if (referenceWhy.empty() && pipeline.outputs().find("reference.final") &&
                std::find(request.outputs.begin(), request.outputs.end(), "reference.final") != request.outputs.end())
                abReference_ = session_.readRaw("reference.final");
        }
    } else {
        pipeline.bindCamera(session_.camera());
        state.report = {};
    }

    makeViewportImage(state, viewportWhy);
    makeSideImage(state, sideWhy);
}

void ViewportComposer::makeViewportImage(UiState& state, const std::string& viewportWhy) {
    Pipeline& pipeline = session_.pipeline();
    const bool deferred = state.viewport.mode == DisplayMode::Deferred;
    const gl::Texture* base = nullptr;
    const gl::Texture* depth = nullptr;
    keepHistogram(state.viewportImage);
    if (!deferred) {
        const auto mode = state.viewport.mode == DisplayMode::Textured ? ForwardPreview::Mode::Textured
                                                                          : ForwardPreview::Mode::Wireframe;
        base = &forward_.render(pipeline.gpuScene(), pipeline.width(), pipeline.height(), mode,
                                DepthConvention::fromUniform(pipeline.lastCamera().depth));
        depth = &forward_.depth();
    } else if (!viewportWhy.empty()) {
        state.viewportImage.unavailable = viewportWhy;
    } else {
        const PublishedOutput* o = pipeline.outputs().find(state.viewport.output);
        if (isDisplayReady(*o)) {
            base = o->texture;
        } else {
            BufferViewSettings s = state.viewport.settingsOr();
            s.nearPlane = session_.camera().nearPlane;
            s.farPlane = session_.camera().farPlane;
            s.reversedDepth = pipeline.lastCamera().depth.x > 0.5f;
            base = &session_.bufferView().render(*o, s);
            if (BufferView::resolveAutoRange(o->decl.kind, s)) {
                std::tie(state.viewportImage.autoLo, state.viewportImage.autoHi) = session_.bufferView().lastAutoRange();
                state.viewportImage.haveAutoRange = true;
            }
        }
        histogram(state.viewport, *o, state.viewportImage, state);
        depth = pipeline.outputs().find("gbuffer.depth")->texture;
    }
    if (base) {
        const OverlaySettings& ov = state.viewport.overlay;
        if (ov.lightVolumes || ov.axes) {
            OverlaySettings s = ov;
            s.onlySelected = state.viewport.volumes == VolumeFilter::Selected;
            s.onlySubset = state.viewport.volumes == VolumeFilter::AtProbe;
            s.subset = state.probe.lights;
            s.threshold = static_cast<float>(session_.knobs().value(*session_.knobs().find("lighting.threshold")));
            s.sphereSubdivisions = static_cast<int>(session_.knobs().value(*session_.knobs().find("lighting.volume_subdivisions")));
            base = &overlay_.compose(*base, depth, session_.scene(), pipeline.lastCamera(), s);
        }
        state.viewportImage.texture = base->id();
        state.viewportImage.width = base->width();
        state.viewportImage.height = base->height();
    }
}

void ViewportComposer::makeSideImage(UiState& state, const std::string& sideWhy) {
    Pipeline& pipeline = session_.pipeline();
    keepHistogram(state.sideImage);
    if (state.panels.sideView) {
        if (!sideWhy.empty()) {
            state.sideImage.unavailable = sideWhy;
        } else if (const PublishedOutput* o = pipeline.outputs().find(state.side.output)) {
            BufferViewSettings s = state.side.settingsOr();
            s.nearPlane = session_.camera().nearPlane;
            s.farPlane = session_.camera().farPlane;
            s.reversedDepth = pipeline.lastCamera().depth.x > 0.5f;
            const gl::Texture& t = isDisplayReady(*o) ? *o->texture : sideView_.render(*o, s);
            if (!isDisplayReady(*o) && BufferView::resolveAutoRange(o->decl.kind, s)) {
                std::tie(state.sideImage.autoLo, state.sideImage.autoHi) = sideView_.lastAutoRange();
                state.sideImage.haveAutoRange = true;
            }
            state.sideImage.texture = t.id();
            state.sideImage.width = t.width();
            state.sideImage.height = t.height();
            histogram(state.side, *o, state.sideImage, state);
        }
    }
}

// A new frame's image, keeping the last histogram (it is recomputed only now and then).
void ViewportComposer::keepHistogram(ShownImage& img) {
    ShownImage next;
    next.histogram = std::move(img.histogram);
    next.histogramOf = std::move(img.histogramOf);
    next.histogramFrame = img.histogramFrame;
    next.histogramUiFrame = img.histogramUiFrame;
    next.haveNonFinite = img.haveNonFinite;
    next.nonFinite = std::move(img.nonFinite);
    img = std::move(next);
}
// The raw values of the shown output, binned, when the view asks for it:
// a read-back of the whole buffer, so at most every 10 frames for the
// same output.
void ViewportComposer::histogram(const ImageView& view, const PublishedOutput& o, ShownImage& img, const UiState& state) {
    const bool nonFiniteView =
        BufferView::resolveMapping(o.decl.kind, view.settingsOr()) == BufferViewSettings::Mapping::NonFinite;
    if (!view.histogram && !nonFiniteView) return;
    const std::string key = o.decl.name + "/" + std::to_string(view.settingsOr().layer) + "/" +
                            std::to_string(view.settingsOr().sample);
    // The same output of the same frame: nothing new. While frames keep
    // coming, at most every 10 UI frames for the same output.
    if (img.histogramOf == key && (img.histogramFrame == state.report.frameIndex || state.frame < img.histogramUiFrame + 10)) return;
    try {
        const FloatImage raw = readOutputRaw(o, view.settingsOr().selection());
        img.histogram = computeHistogram(raw, 128);
        img.nonFinite = FiniteCheck::count(raw, o.decl.name);
        img.haveNonFinite = true;
    } catch (const std::exception&) {
        img.histogram = {};  // outputs that cannot be read back as an image (tables) have none
        img.haveNonFinite = false;
    }
    img.histogramOf = key;
    img.histogramFrame = state.report.frameIndex;
    img.histogramUiFrame = state.frame;
}

// The histograms of the images on show when a view asks for one between frames.
void ViewportComposer::refreshHistograms(UiState& state) {
    Pipeline& pipeline = session_.pipeline();
    if (state.viewport.mode == DisplayMode::Deferred && state.viewportImage.unavailable.empty() && state.framesRendered > 0)
        if (const PublishedOutput* o = pipeline.outputs().find(state.viewport.output)) histogram(state.viewport, *o, state.viewportImage, state);
    if (state.panels.sideView && state.sideImage.unavailable.empty() && state.framesRendered > 0)
        if (const PublishedOutput* o = pipeline.outputs().find(state.side.output)) histogram(state.side, *o, state.sideImage, state);
}

bool ViewportComposer::abActive(const UiState& state) {
    return state.ab.enabled && state.viewport.mode == DisplayMode::Deferred && state.viewport.output == "final";
}

void ViewportComposer::pin(UiState& state) {
    if (state.viewport.mode != DisplayMode::Deferred || state.framesRendered == 0) {
        state.log.error("Pin: only the deferred final image can be pinned", state.time, "pin");
        return;
    }
    try {
        // The pipeline's last frame is A's (the preset side renders first).
        pinned_ = session_.readRaw("final");
    } catch (const std::exception& e) {
        state.log.error(std::string("Pin: ") + e.what(), state.time, "pin");
        return;
    }
    pinnedMs_ = state.ab.a.gpuMs;
    pinnedDescribe_ = "pinned at frame " + std::to_string(state.report.frameIndex);
    state.ab.enabled = true;
    state.ab.source = AbSource::Pinned;
    ++state.ab.generation;
    state.log.done("the current image is pinned as B", state.time, "pin");
}

void ViewportComposer::renderPresetSide(UiState& state) {
    AbView& ab = state.ab;
    abB_ = FloatImage{};
    presetError_.clear();
    presetIgnored_ = 0;
    try {
        if (ab.preset.empty()) throw Error("no preset chosen for B");
        if (ab.preset != presetName_ || !preset_) {
            presetName_.clear();
            RunConfig run;
            run.setPreset(ab.preset);  // a built-in name or a file, as --preset takes it
            preset_ = *run.preset();
            presetName_ = ab.preset;
        }
    } catch (const std::exception& e) {
        presetError_ = "preset '" + ab.preset + "': " + e.what();
        return;
    }
    KnobRegistry& knobs = session_.knobs();
    std::vector<double> saved(knobs.size());
    for (size_t i = 0; i < knobs.size(); ++i) saved[i] = knobs.value(static_cast<int>(i));
    presetIgnored_ = static_cast<int>(preset_->applyKnobs(knobs).ignored.size());
    // B's own AOV cost (issue 22): a preset whose AOV frame would take minutes
    // is not rendered (the window would freeze); A is kept and the numbers
    // line says why. The estimate is AovCostGuard's, at the same size.
    const std::string costly =
        AovCostEstimate::check(knobs, session_.scene(), session_.camera(), state.renderSize.x, state.renderSize.y);
    if (!costly.empty()) {
        presetError_ = "preset '" + ab.preset + "' not rendered: " + costly;
    } else {
        try {
            const FrameReport r = session_.pipeline().render(session_.camera(), FrameRequest{{"final"}});
            abFramesB_.insert(r.frameIndex);
            abB_ = session_.readRaw("final");
        } catch (const std::exception& e) {
            presetError_ = "preset '" + ab.preset + "' does not render: " + e.what();
        }
    }
    // The current settings back, whatever happened.
    for (size_t i = 0; i < knobs.size(); ++i)
        if (knobs.value(static_cast<int>(i)) != saved[i]) knobs.set(static_cast<int>(i), saved[i]);
}

void ViewportComposer::composeAb(UiState& state) {
    AbView& ab = state.ab;
    ab.ready = false;
    ab.unavailable.clear();
    const FloatImage* b = nullptr;
    switch (ab.source) {
        case AbSource::Pinned:
            ab.describeB = pinnedDescribe_;
            if (pinned_.pixels.empty()) ab.unavailable = "nothing pinned yet: Pin (or the p key) takes the current image as B";
            else b = &pinned_;
            break;
        case AbSource::Preset:
            ab.describeB = "preset " + ab.preset + (presetIgnored_ ? " (" + std::to_string(presetIgnored_) + " keys ignored)" : "");
            if (!presetError_.empty()) ab.unavailable = presetError_;
            else b = &abB_;
            break;
        case AbSource::Reference:
            ab.describeB = "CPU reference";
            if (abReference_.pixels.empty())
                ab.unavailable = "no CPU reference of this view yet: Render > CPU reference of this view (F9)";
            else b = &abReference_;
            break;
    }
    if (!b) return;
    if (abA_.pixels.empty()) {
        ab.unavailable = "no image of the current settings yet";
        return;
    }
    if (b->width != abA_.width || b->height != abA_.height) {
        ab.unavailable = "B is " + std::to_string(b->width) + "x" + std::to_string(b->height) + ", the view " +
                         std::to_string(abA_.width) + "x" + std::to_string(abA_.height) +
                         (ab.source == AbSource::Pinned ? ": pin again" : "");
        return;
    }
    try {
        split_.set(abA_, *b);
        split_.makeHeatMap(ab.display == AbDisplay::Flip ? SplitComparison::Map::Flip : SplitComparison::Map::Difference);
        const ImageComparison& c = split_.comparison();
        ab.rms = c.difference.overall.rms;
        ab.psnr = c.difference.overall.psnr;
        ab.meanAbsolute = c.difference.overall.mean;
        ab.haveFlip = c.flip.has_value();
        ab.flip = c.flip ? c.flip->mean : 0.0;
        // Each side against the CPU reference, when one is shown.
        ab.a.haveError = ab.b.haveError = false;
        if (!abReference_.pixels.empty() && abReference_.width == abA_.width && abReference_.height == abA_.height) {
            ComparisonSettings ldr;
            auto against = [&](const FloatImage& img, AbSide& side) {
                const ImageComparison r = ImageComparison::measure(abReference_, img, ldr, "reference", "image");
                side.haveError = true;
                side.rms = r.difference.overall.rms;
                side.flip = r.flip ? r.flip->mean : 0.0;
            };
            against(abA_, ab.a);
            if (ab.source == AbSource::Reference) {
                ab.b.haveError = true;
                ab.b.rms = ab.b.flip = 0.0;
            } else {
                against(*b, ab.b);
            }
        }
    } catch (const std::exception& e) {
        ab.unavailable = std::string("A/B: ") + e.what();
        return;
    }
    ab.textureA = split_.textureA().id();
    ab.textureB = split_.textureB().id();
    ab.heatTexture = split_.heatMap().id();
    ab.heatHigh = split_.heatHigh();
    ab.width = abA_.width;
    ab.height = abA_.height;
    ab.ready = true;
}

void ViewportComposer::abTimes(UiState& state) {
    AbView& ab = state.ab;
    ab.a.gpuMs.clear();
    ab.b.gpuMs.clear();
    if (const PassTimer::Series* total = session_.pipeline().timer().find(PassTimer::kFrameSeries))
        for (const auto& s : total->samples) {
            if (abFramesA_.count(s.frame)) ab.a.gpuMs.push_back(s.gpuMs);
            else if (abFramesB_.count(s.frame)) ab.b.gpuMs.push_back(s.gpuMs);
        }
    if (ab.source == AbSource::Pinned) ab.b.gpuMs = pinnedMs_;
    ab.gpuDifference = ab.a.gpuMs.size() >= 3 && ab.b.gpuMs.size() >= 3
                           ? bootstrapDifferenceOfMedians(ab.a.gpuMs, ab.b.gpuMs)
                           : DifferenceInterval{};
}

void ViewportComposer::logFrameWarnings(UiState& state) {
    std::string joined;
    const std::vector<std::string> warnings = state.report.warnings();
    for (const auto& w : warnings) joined += w + "\n";
    if (joined == lastFrameWarnings_) return;
    // A loss that changes every frame (an animated scene, a moving camera) is
    // logged at most every kFrameWarningSeconds, so Messages is not flooded.
    const bool appeared = lastFrameWarnings_.empty();
    if (!appeared && !joined.empty() && state.time - lastFrameWarningTime_ < kFrameWarningSeconds) return;
    lastFrameWarnings_ = joined;
    lastFrameWarningTime_ = state.time;
    for (const auto& w : warnings) state.log.info("warning: " + w, state.time);
}

}  // namespace dw::ui
