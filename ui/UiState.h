#pragma once
// Everything the panels share: which panels are open, what the viewport and
// the side view show, the light selection, the probe, the message log, and
// requests for the app's frame loop. No GL here; panels only show textures the
// renderer already owns.
#include <cstdint>
#include <deque>
#include <map>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "renderer/bench/QuickSweep.h"
#include "renderer/study/ErrorAttribution.h"
#include "renderer/bench/ChangeMeasurement.h"
#include "renderer/inspect/BufferView.h"
#include "renderer/inspect/FiniteCheck.h"
#include "renderer/io/ImageHistogram.h"
#include "renderer/inspect/PixelProbe.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/RunConfig.h"
#include "renderer/inspect/ViewportOverlay.h"
#include "renderer/scene/LightAnimator.h"
#include "ui/AbView.h"
#include "ui/FitBudgetRun.h"
#include "ui/RecordMeasurement.h"
#include "ui/SceneTimeline.h"

namespace dw::gl {
class Sampler;
}

namespace dw::ui {

enum class DisplayMode { Deferred, Textured, Wireframe };
enum class CameraMode { Orbit, Fly };

struct PanelFlags {
    bool viewport = true;
    bool inspector = true;
    bool probe = true;
    bool lights = true;
    bool scene = true;
    bool timings = true;
    bool knobs = true;
    bool presets = true;
    bool messages = true;
    bool sideView = false;
    bool keys = false;
    bool pareto = false;
};

struct Message {
    double time = 0.0;
    bool error = false;
    std::string text;
    std::string action;  // what the user did ("open scene", "save preset", ...); may be empty
};

// Every message of the session, the error banner over the viewport, and a
// short toast for things done that leave no other visible trace (a file
// written). An error names its action; when that action later succeeds
// (succeeded()), its banner goes away, so a failed scene load does not stay
// over the scene that loaded after it.
class MessageLog {
public:
    static constexpr double kToastSeconds = 4.0;
    // A longer message is cut there, its length said ("... (N more bytes)").
    static constexpr size_t kMaxMessageBytes = 2000;

    void info(const std::string& text, double time);
    void error(const std::string& text, double time, const std::string& action = {});
    // info() that also shows as a toast.
    void done(const std::string& text, double time, const std::string& action = {});
    // `action` worked: an error banner it raised is cleared.
    void succeeded(const std::string& action);
    const std::deque<Message>& all() const { return messages_; }
    // The newest error not yet dismissed, shown as a banner over the viewport.
    const Message* banner() const { return bannerIndex_ >= 0 ? &messages_[static_cast<size_t>(bannerIndex_)] : nullptr; }
    void dismissBanner() { bannerIndex_ = -1; }
    // The newest toast, while it is younger than kToastSeconds at `now`.
    const Message* toast(double now) const;

private:
    void push(Message m);
    std::deque<Message> messages_;
    long bannerIndex_ = -1;
    long toastIndex_ = -1;
};

// A texture the renderer produced for the UI to show this frame.
struct ShownImage {
    unsigned texture = 0;
    int width = 0, height = 0;
    std::string unavailable;  // why there is no image (e.g. the pass did not run)
    // The raw values' histogram (when the view asked for one), and the
    // output and frame it was taken from.
    ImageHistogram histogram;
    std::string histogramOf;
    std::uint64_t histogramFrame = 0;    // the rendered frame (FrameReport::frameIndex)
    std::uint64_t histogramUiFrame = 0;  // the UI frame it was taken in
    // The shown values' NaN / +Inf / -Inf counts and first pixel (with the
    // histogram, and whenever the non-finite mapping is shown).
    bool haveNonFinite = false;
    NonFiniteCount nonFinite;
    // The automatic range the view used (BufferView::lastAutoRange), per channel.
    bool haveAutoRange = false;
    glm::vec4 autoLo{0.0f}, autoHi{0.0f};
};

// One image view (the viewport, the side view), as a texture viewer:
// display settings, zoom, pan and the histogram remembered per output (R +
// heat map and a 16x zoom chosen for the L-buffer do not carry over to the
// AO buffer, and coming back to the L-buffer finds them again).
struct ImageView {
    // The output shown; change it with show(), which keeps each output's view.
    std::string output;
    std::map<std::string, BufferViewSettings> settingsByOutput;
    BufferViewSettings& settings() { return settingsByOutput[output]; }
    BufferViewSettings settingsOr() const {
        const auto it = settingsByOutput.find(output);
        return it == settingsByOutput.end() ? BufferViewSettings{} : it->second;
    }
    float zoom = 1.0f;          // 1: the whole image fits the view; 2: twice as large; ...
    float fitScale = 1.0f;      // screen pixels per image pixel at zoom 1 (set when drawn)
    glm::vec2 center{0.5f};     // the image point at the view's centre (u right, v down, 0..1)
    bool histogram = false;
    // "exr" or "png" when *save* was chosen: the app writes the shown output
    // at its own resolution (EXR raw values, PNG as shown) and clears it.
    std::string saveRequest;

    // Shows `name`: the current output's zoom, pan and histogram are kept,
    // and `name`'s own (or the defaults: fit, no histogram) come back.
    void show(const std::string& name);

private:
    struct Framing {
        float zoom = 1.0f;
        glm::vec2 center{0.5f};
        bool histogram = false;
    };
    std::map<std::string, Framing> framingByOutput_;
};

// Where an image of `imageSize` pixels lies on screen when shown in a box at
// `boxMin` of `boxSize` by `view`'s zoom and pan (it may reach past the box;
// draw it clipped), and the reverse: the image's (u, v) at a screen point.
struct ImagePlacement {
    glm::vec2 min{0.0f}, size{0.0f};
    float fitScale = 1.0f;  // screen pixels per image pixel at zoom 1
    glm::vec2 uvAt(glm::vec2 screen) const { return (screen - min) / glm::max(size, glm::vec2(1e-6f)); }
};
ImagePlacement placeImage(glm::vec2 imageSize, glm::vec2 boxMin, glm::vec2 boxSize, const ImageView& view);
// Zooms by `factor` keeping the image point under `screen` where it is.
void zoomAt(ImageView& view, float factor, glm::vec2 screen, const ImagePlacement& before);

// The render resolution against the viewport panel's size, for slow GL
// (llvmpipe): full, half, quarter, or automatic, which steps the scale to
// hold a frame-time target.
enum class ResolutionScale { Full, Half, Quarter, Auto };

// Which light volumes the overlay draws: those at the probed pixel (the
// default: what the pixel sees, readable in a scene of many lights), all, or
// the light selected in the Lights panel.
enum class VolumeFilter { AtProbe, All, Selected };

struct ViewportView : ImageView {
    ViewportView() { output = "final"; }
    DisplayMode mode = DisplayMode::Deferred;
    OverlaySettings overlay;
    VolumeFilter volumes = VolumeFilter::AtProbe;
    CameraMode camera = CameraMode::Orbit;
    ResolutionScale resolution = ResolutionScale::Full;
    float frameTargetMs = 100.0f;  // Auto: the GPU frame time to stay under
    float autoScale = 1.0f;        // Auto: the scale it settled on (1/8 .. 1)
    // The renderer's name when it rasterises on the CPU and the window
    // started at a reduced scale because of it (the toolbar says so, with
    // full resolution one click away); empty otherwise.
    std::string softwareStart;
    float scale() const {
        switch (resolution) {
            case ResolutionScale::Full: return 1.0f;
            case ResolutionScale::Half: return 0.5f;
            case ResolutionScale::Quarter: return 0.25f;
            case ResolutionScale::Auto: return autoScale;
        }
        return 1.0f;
    }
};

// The next automatic scale from the newest GPU frame times (ms): a step down
// when over the target, a step up when well under it, else unchanged;
// between 1/8 and 1. Steps are 0.8x and 1.25x, so it settles, not oscillates
// (under half the target to step up, which 1.25^2 = 1.56x more pixels keeps under).
float nextAutoScale(float scale, float frameMs, float targetMs);

// The resolution the window starts at: `option` (--resolution) when given;
// else on a CPU rasteriser (llvmpipe: a frame of the default scene at the
// default window size takes 1.5 s) auto scaling from 1/4 with a 150 ms
// target, so a camera step shows within about 0.2 s; else full. Scripted
// runs (tests, screenshots) keep full unless told, so their images do not
// depend on the machine's speed.
struct StartResolution {
    ResolutionScale scale = ResolutionScale::Full;
    float autoScale = 1.0f;
    float frameTargetMs = 100.0f;
    bool softwareDefault = false;  // chosen because of the CPU rasteriser
};
StartResolution startResolution(const std::string& option, bool cpuRasterizer, bool scripted);

struct SideView : ImageView {
    SideView() { output = "gbuffer.normal"; }
};

struct ProbeState {
    bool hovering = false;    // the cursor is over the viewport image this frame
    bool pinned = false;      // a click fixed the probe to a pixel
    glm::ivec2 pixel{0, 0};   // in render pixels, rows top-down
    ProbeResult result;
    // Where the pixel sits in the viewport image, for the magnifier.
    glm::vec2 uv{0.0f};
    // The point and spot lights whose volumes contain the probed surface
    // point (lightsCovering), one line each for the panel, and how many
    // directional lights light it besides.
    std::vector<int> lights;
    std::vector<std::string> lightLines;
    int directionalLights = 0;
};

struct UiState {
    PanelFlags panels;
    ViewportView viewport;
    SideView side;
    AbView ab;  // the viewport's A/B split
    ProbeState probe;
    MessageLog log;
    LightAnimator animator;
    SceneTimeline timeline;  // the scene's glTF animation: its time, play, loop, speed
    int selectedLight = -1;
    std::string presetsDir;
    std::string scenesDir;
    // The start-up scene, preset and --set: every scene opened starts from
    // the defaults, its settings, this preset, then these --set values.
    RunConfig run;
    bool resetLayout = true;
    // The preset loaded or saved last, and the knob values right after it,
    // so the Presets panel can say "modified since".
    std::string activePreset;
    std::vector<double> activePresetKnobs;
    // Where screenshots and timing CSVs go (absolute; created when first used).
    std::string exportDir;

    // Filled by the app each frame for the panels to read.
    FrameReport report;
    ShownImage viewportImage, sideImage;
    glm::ivec2 renderSize{0, 0};   // what the pipeline renders at
    glm::ivec2 wantedSize{0, 0};   // what the viewport panel has room for
    std::deque<float> cpuFrameMs;  // app frame time, newest last
    // Nearest-neighbour sampling for images zoomed to pixel level (the app
    // owns it; the panels bind it around their image draws).
    const gl::Sampler* nearestSampler = nullptr;
    // Timing capture: render every frame (for the timings panel) and freeze
    // the resolution scale. Off: a frame is rendered only when something it
    // depends on changed (camera, knobs, scene, lights, view, size).
    bool timingCapture = false;
    std::uint64_t framesRendered = 0;  // frames the pipeline actually rendered
    // The first frame of the current configuration (scene and render size):
    // timings of frames before it no longer compare.
    std::uint64_t configSince = 0;
    // The cost of a change: the timings panel starts it, the frame loop
    // renders its frames one a UI frame (ChangeMeasurement).
    ChangeMeasurement measure;
    // Bumped each time AovCostGuard puts the knobs back (a refused state):
    // the timings panel takes the values put back as committed, not as a
    // change of the user's, and forgets the refused change (measure would
    // render it).
    std::uint64_t knobsPutBack = 0;
    // The Pareto panel's quick sweep of one knob: the frame loop renders its
    // frames (one a UI frame, before the view's own, so the viewport never
    // shows a swept value).
    QuickSweep sweep;
    // The Pareto panel's attribution of the view's error (AttributionView):
    // the frame loop renders one configuration a UI frame, before the view's own.
    AttributionRun attribution;
    // The Pareto panel's *fit budget* sweep (FitBudgetRun): the frame loop
    // renders one of its frames a UI frame, before the view's own.
    FitBudgetRun fitBudget;
    // File > Save record's measurement of the state on show: the frame loop
    // renders its frames (one a UI frame, before the view's own) and writes
    // the record after the last (RecordMeasurement).
    RecordMeasurement recordRun;
    // Timer results still in flight or a measurement running: the frame loop
    // must keep polling (never sleep waiting for input) until this is false.
    bool timingsPending = false;
    std::uint64_t shaderGeneration = 0;  // bumped by every shader reload (a reason to render again)
    glm::vec3 cameraPosition{0.0f}; // after the last frame (the scripted mode reports it)
    std::uint64_t frame = 0;
    double time = 0.0;

    // Keys pressed this frame (GLFW key, modifier bits), in order, as the
    // input queue handed them to ImGui (ui/InputQueue): shortcuts read these,
    // so a tap shorter than a frame still counts.
    std::vector<std::pair<int, int>> keyPresses;
    // Files dropped on the window this frame (opened as scenes).
    std::vector<std::string> droppedFiles;
    // Scene files opened, newest first (kept in layout.json between sessions).
    static constexpr size_t kRecentScenes = 10;
    std::deque<std::string> recentScenes;

    // Requests the app carries out after the UI is drawn.
    bool requestScreenshot = false;
    bool requestRenderDocCapture = false;
    bool requestReference = false;  // F9, Render > CPU reference of this view
    bool requestReferenceCancel = false;  // cancel the CPU reference being traced (the Pareto panel's wait)
    // The CPU reference's job as ReferenceControls::update left it this frame:
    // its progress (0..1) while one is traced, else -1; and how many jobs have
    // ended (a result taken, shown or not, or an error), so a panel waiting for
    // one knows when it is over.
    double referenceProgress = -1.0;
    std::uint64_t referenceJobsEnded = 0;
    // While the CPU reference is rendered or shown (ReferenceControls), the
    // view holds still: the auto resolution scale keeps its step, and the
    // fire scene's flames stay where they were for frame heldFlameFrame.
    bool holdView = false;
    std::optional<std::uint64_t> heldFlameFrame;
    std::uint64_t flameFrame = 0;  // the frame index the flames were last placed for
    bool forceRender = false;  // render the next frame even if nothing changed (a capture of it)
    // RenderDoc, as the app found it: whether captures can be taken, why not, and the captures taken.
    bool renderdocAvailable = false;
    std::string renderdocWhy;
    std::vector<std::string> renderdocCaptures;
    bool requestReloadShaders = false;
    // File > Open scene (Ctrl+O): the Scene panel opens with its path field focused.
    bool requestOpenScene = false;
    bool requestQuit = false;
    std::string requestTimingsCsv;
};

}  // namespace dw::ui
