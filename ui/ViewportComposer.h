#pragma once
// The viewport's composition (DESIGN.md "ui/": images, overlays, A/B split):
// each UI frame, renders the pipeline when something the images depend on
// changed, and prepares what the viewport and the side view show (the final
// image, a buffer view, a forward preview, the light-volume overlay), their
// histograms and the probe. It owns the renderer-side helpers that make those
// images (BufferView, ForwardPreview, ViewportOverlay); it creates no GL
// object itself. Moved out of app/GuiApp.cpp (issue 23), unchanged.
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/gl/Sampler.h"
#include "renderer/inspect/BufferView.h"
#include "renderer/inspect/ForwardPreview.h"
#include "renderer/inspect/SplitComparison.h"
#include "renderer/knobs/Preset.h"
#include "renderer/inspect/ViewportOverlay.h"
#include "ui/UiState.h"

namespace dw::ui {

class ViewportComposer {
public:
    explicit ViewportComposer(RenderSession& session);
    const gl::Sampler& nearestSampler() const { return nearest_; }
    // The A/B split's last measured pair (UiState::ab says whether it is ready).
    const SplitComparison& abImages() const { return split_; }

    // Once a UI frame, before the panels draw: followViewport,
    // stepBackgroundWork and renderOnChange in turn (the window's loop,
    // GuiLoop, calls them one by one).
    void render(UiState& state);
    // The render size follows the viewport panel (targetSize); the light animation advances.
    void followViewport(UiState& state);
    // The work that renders frames of its own between UI frames takes its
    // step: a change measured (this frame renders the knob values of its
    // side), a quick sweep's step, File > Save record's measured frame.
    void stepBackgroundWork(UiState& state);
    // The pipeline rendered when what the images depend on changed (or
    // timings are captured, a change is measured, the A/B view needs frames),
    // the viewport's and the side view's images made, the timer polled, the probe read.
    void renderOnChange(UiState& state);
    // The size (pixels, at least 16 x 16) this frame renders at: the viewport
    // panel's wanted size times the resolution scale; state.renderSize until
    // the panel has a size.
    static glm::ivec2 targetSize(const UiState& state);
    // The lights whose volumes contain the probed surface point.
    void probeLights(UiState& state);

private:
    std::string frameSignature(const UiState& state) const;
    void adjustAutoScale(UiState& state);
    // The pipeline rendered with the final image and what the viewport and
    // the side view show (each checked with Pipeline::plan first: an output
    // whose pass cannot run shows why), then their images made.
    void renderImages(UiState& state);
    // The viewport's image: the final image, a buffer view, or a forward mode; then overlays.
    void makeViewportImage(UiState& state, const std::string& viewportWhy);
    // The side view's image: the buffer it shows, through its own BufferView.
    void makeSideImage(UiState& state, const std::string& sideWhy);
    static void keepHistogram(ShownImage& img);
    void histogram(const ImageView& view, const PublishedOutput& o, ShownImage& img, const UiState& state);
    void refreshHistograms(UiState& state);
    // The passes' warnings about the frame (the oit pass's lost fragments)
    // into Messages, once each time they change (not every frame they hold;
    // at most every kFrameWarningSeconds while they keep changing).
    void logFrameWarnings(UiState& state);
    static constexpr double kFrameWarningSeconds = 2.0;

    // The A/B split (AbView): on for the deferred final image.
    static bool abActive(const UiState& state);
    void pin(UiState& state);
    // B under a preset: the preset over the current knobs, rendered, read back, the knobs put back.
    void renderPresetSide(UiState& state);
    // A against B (SplitComparison), each against the reference, into state.ab.
    void composeAb(UiState& state);
    // Each side's GPU frame times since the view changed, and their difference's interval.
    void abTimes(UiState& state);
    static constexpr size_t kAbFrames = 10;  // frames per side rendered for the times

    RenderSession& session_;
    bool measuring_ = false;  // this frame renders a measured change's side (stepBackgroundWork)
    BufferView sideView_;
    ForwardPreview forward_;
    ViewportOverlay overlay_;
    gl::Sampler nearest_;
    std::string lastSignature_;
    std::string lastConfig_;
    std::string lastFrameWarnings_;
    double lastFrameWarningTime_ = 0.0;
    SplitComparison split_;
    FloatImage abA_, abB_, abReference_, pinned_;
    std::vector<double> pinnedMs_;
    std::string pinnedDescribe_;
    std::set<std::uint64_t> abFramesA_, abFramesB_;
    size_t abRenders_ = 0;  // renders since the view last changed
    std::string composedSignature_;
    std::optional<Preset> preset_;
    std::string presetName_, presetError_;
    int presetIgnored_ = 0;
};

}  // namespace dw::ui
