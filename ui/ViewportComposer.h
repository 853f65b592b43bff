#pragma once
// The viewport's composition (DESIGN.md "ui/": images, overlays):
// each UI frame, renders the pipeline when something the images depend on
// changed, and prepares what the viewport and the side view show (the final
// image, a buffer view, a forward preview, the light-volume overlay), their
// histograms and the probe. It owns the renderer-side helpers that make those
// images (BufferView, ForwardPreview, ViewportOverlay); it creates no GL
// object itself. Moved out of app/GuiApp.cpp (issue 23), unchanged.
#include <string>

#include "renderer/RenderSession.h"
#include "renderer/gl/Sampler.h"
#include "renderer/inspect/BufferView.h"
#include "renderer/inspect/ForwardPreview.h"
#include "renderer/inspect/ViewportOverlay.h"
#include "ui/UiState.h"

namespace dw::ui {

class ViewportComposer {
public:
    explicit ViewportComposer(RenderSession& session);
    const gl::Sampler& nearestSampler() const { return nearest_; }

    // Once a UI frame, before the panels draw.
    void render(UiState& state);
    // The lights whose volumes contain the probed surface point.
    void probeLights(UiState& state);

private:
    std::string frameSignature(const UiState& state) const;
    void adjustAutoScale(UiState& state);
    void renderImages(UiState& state);
    static void keepHistogram(ShownImage& img);
    void histogram(const ImageView& view, const PublishedOutput& o, ShownImage& img, const UiState& state);
    void refreshHistograms(UiState& state);

    RenderSession& session_;
    BufferView sideView_;
    ForwardPreview forward_;
    ViewportOverlay overlay_;
    gl::Sampler nearest_;
    std::string lastSignature_;
    std::string lastConfig_;
};

}  // namespace dw::ui
