#include "app/GuiApp.h"

#include <nlohmann/json.hpp>

#include <epoxy/gl.h>
// epoxy must come before GLFW so GLFW does not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <tuple>
#include <type_traits>

#include "app/CommandLine.h"
#include "app/RenderDocCapture.h"
#include "app/ScriptedInput.h"
#include "renderer/Error.h"
#include "renderer/gl/Sampler.h"
#include "renderer/io/ImageHistogram.h"
#include "renderer/lighting/LightVolume.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "ui/RecordDialog.h"
#include "renderer/inspect/ForwardPreview.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/RenderSession.h"
#include "renderer/passes/ReferencePass.h"
#include "renderer/inspect/ViewportOverlay.h"
#include "ui/InputQueue.h"
#include "ui/Widgets.h"
#include "ui/WorkbenchUi.h"

#include <imgui_internal.h>

namespace dw {

namespace fs = std::filesystem;

namespace {

std::string& glfwErrorText() {
    static std::string text;
    return text;
}

void onGlfwError(int code, const char* description) {
    glfwErrorText() = description ? description : ("GLFW error " + std::to_string(code));
}

// GLFW and ImGui set up and torn down in the right order.
class Window {
public:
    // `egl`: create the context through EGL instead of the platform's own API.
    Window(int width, int height, bool vsync, bool egl) {
        glfwSetErrorCallback(onGlfwError);
        if (!glfwInit())
            throw GlUnsupportedError("cannot open a window (" + glfwErrorText() +
                                     "); use 'deferred-workbench render --scene S --out image.png' to render headless");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        // Under RenderDoc (1.24) the GLX context's frames fail: its GLX layer
        // reports our framebuffers as having no attachments. Through EGL, the
        // API the headless renderer uses, RenderDoc captures complete frames;
        // GLX stays the default otherwise, and the fallback if EGL fails.
        if (egl) glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
        window_ = glfwCreateWindow(width, height, "Deferred Workbench", nullptr, nullptr);
        if (!window_ && egl) {
            eglFailed_ = glfwErrorText();
            glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_NATIVE_CONTEXT_API);
            window_ = glfwCreateWindow(width, height, "Deferred Workbench", nullptr, nullptr);
        }
        if (!window_) {
            glfwTerminate();
            throw GlUnsupportedError("cannot create an OpenGL 4.5 core window (" + glfwErrorText() +
                                     "); 'deferred-workbench render' works headless");
        }
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(vsync ? 1 : 0);
    }
    ~Window() {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;
    GLFWwindow* get() const { return window_; }
    // Why an EGL context was asked for and not had ("" when it was, or not asked).
    const std::string& eglFailed() const { return eglFailed_; }

private:
    GLFWwindow* window_ = nullptr;
    std::string eglFailed_;
};

// The window's input events, queued in arrival order for ui::InputQueue to
// hand to ImGui a change per key or button per frame (the callbacks have no
// user pointer to reach the frame loop through: GLFW's is ImGui's backend's).
ui::InputQueue& inputQueue() {
    static ui::InputQueue queue;
    return queue;
}
// Files dropped on the window since the last frame.
std::vector<std::string>& droppedFiles() {
    static std::vector<std::string> files;
    return files;
}

void onKey(GLFWwindow*, int key, int, int action, int mods) {
    if (action != GLFW_REPEAT) inputQueue().key(key, action == GLFW_PRESS, mods);
}
void onChar(GLFWwindow*, unsigned codepoint) { inputQueue().character(codepoint); }
void onMouseButton(GLFWwindow* window, int button, int action, int) {
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    inputQueue().button(button, action == GLFW_PRESS, static_cast<float>(x), static_cast<float>(y));
}
void onDrop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) droppedFiles().emplace_back(paths[i]);
}

class ImGuiLayer {
public:
    explicit ImGuiLayer(GLFWwindow* window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        // The layout is the project's own (layout.json): panels are placed
        // every frame, so imgui.ini would hold nothing worth keeping.
        io.IniFilename = nullptr;
        ImGui::StyleColorsDark();
        ImGuiStyle& style = ImGui::GetStyle();
        style.WindowRounding = 2.0f;
        style.FrameRounding = 2.0f;
        style.WindowPadding = ImVec2(6, 6);
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        // Keys, text and buttons go through the input queue instead of
        // ImGui's callbacks (which set state a frame can miss); the wheel,
        // cursor and focus stay with the backend.
        glfwSetKeyCallback(window, onKey);
        glfwSetCharCallback(window, onChar);
        glfwSetMouseButtonCallback(window, onMouseButton);
        glfwSetDropCallback(window, onDrop);
        ImGui_ImplOpenGL3_Init("#version 450 core");
    }
    ~ImGuiLayer() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;
};

std::string configDir() {
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::string(x) + "/deferred-workbench";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.config/deferred-workbench";
    return ".deferred-workbench";
}

std::string exportDirDefault() {
    if (const char* x = std::getenv("XDG_DATA_HOME"); x && *x) return std::string(x) + "/deferred-workbench/exports";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.local/share/deferred-workbench/exports";
    return fs::absolute("deferred-workbench-exports").string();
}

// layout.json: the splitter weights and which panels are open.
// A missing saved layout is no error; a missing --layout file is (readJsonFile says "not found").
void loadLayout(const std::string& path, ui::WorkbenchUi& ui, ui::UiState& state, bool mustExist = false) {
    std::error_code ec;
    if (!mustExist && !fs::exists(path, ec)) return;
    try {
        // Guarded like every JSON the workbench reads (150 000 levels overflowed the stack).
        const nlohmann::json j = readJsonFile(path, {kMaxJsonDepth, false});
        if (!j.is_object()) throw std::runtime_error("expected an object");
        if (j.contains("layout")) ui.layout().fromJson(j["layout"]);
        if (j.contains("open") && j["open"].is_object())
            for (auto it = j["open"].begin(); it != j["open"].end(); ++it)
                if (bool* f = ui::WorkbenchUi::panelFlag(state.panels, it.key()); f && it.value().is_boolean()) *f = it.value().get<bool>();
        if (j.contains("recent_scenes") && j["recent_scenes"].is_array())
            for (const auto& r : j["recent_scenes"])
                if (r.is_string() && state.recentScenes.size() < ui::UiState::kRecentScenes) state.recentScenes.push_back(r.get<std::string>());
        state.resetLayout = false;
    } catch (const std::exception& e) {
        std::string why = e.what();
        if (why.rfind(path + ": ", 0) == 0) why = why.substr(path.size() + 2);  // a FileError names the file already
        state.log.error(path + ": saved layout not used (" + why + "); the default layout is shown", 0.0);
    }
}

void saveLayout(const std::string& path, ui::WorkbenchUi& ui, ui::UiState& state) {
    nlohmann::json open = nlohmann::json::object();
    for (const auto& name : ui.layout().panels())
        if (bool* f = ui::WorkbenchUi::panelFlag(state.panels, name)) open[name] = *f;
    try {
        const nlohmann::json recent = std::vector<std::string>(state.recentScenes.begin(), state.recentScenes.end());
        writeFileAtomically(path, nlohmann::json{{"layout", ui.layout().toJson()}, {"open", open}, {"recent_scenes", recent}}.dump(2) + "\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
    }
}

// Named items drawn in the last frame (ui::noteItem): where, in which panel,
// and the visible part of that panel.
nlohmann::json itemsReport() {
    nlohmann::json items = nlohmann::json::object();
    for (const auto& [name, d] : ui::drawnItems())
        if (d.frame == ImGui::GetFrameCount())
            items[name] = {{"x", d.x}, {"y", d.y}, {"w", d.w}, {"h", d.h}, {"panel", d.window},
                           {"clip", {d.clipX, d.clipY, d.clipW, d.clipH}}};
    return items;
}

// The CPU reference the workbench shows, and the frame's error against it.
nlohmann::json referenceReport(RenderSession& session) {
    const ReferencePass* pass = session.pipeline().pass<ReferencePass>();
    if (!pass || !pass->hasReference()) return {{"shown", false}};
    const ReferencePass::Errors& e = pass->errors();
    return {{"shown", true}, {"stats", pass->stats()}, {"mean_absolute", e.meanAbsolute}, {"rms", e.rms},
            {"max", e.max}, {"mean_relative", e.meanRelative}};
}

// --layout-out: where ImGui drew each panel (its own record, not ours), the
// window size and the probe, for the tests to check.
void writeLayoutReport(const std::string& path, const ui::WorkbenchUi& ui, const ui::UiState& state, int fbw, int fbh,
                       RenderSession& session) {
    const PassTimer& timer = session.pipeline().timer();
    // The newest frame whose GPU times have come back (-1: none).
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    const long long lastTimedFrame =
        total && !total->samples.empty() ? static_cast<long long>(total->samples.back().frame) : -1;
    nlohmann::json errors = nlohmann::json::array();
    for (const ui::Message& m : state.log.all())
        if (m.error) errors.push_back(m.text);
    nlohmann::json panels = nlohmann::json::array();
    for (const auto& d : ui.drawnPanels()) {
        const ImGuiWindow* w = ImGui::FindWindowByName(d.name.c_str());
        if (!w || !w->WasActive) continue;
        panels.push_back({{"name", d.name}, {"x", w->Pos.x}, {"y", w->Pos.y}, {"w", w->Size.x}, {"h", w->Size.y}});
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const nlohmann::json j = {{"display", {display.x, display.y}},
                              {"framebuffer", {fbw, fbh}},
                              {"menu_bar_height", ImGui::GetFrameHeight()},
                              {"panels", panels},
                              {"probe", {{"pinned", state.probe.pinned},
                                         {"pixel", {state.probe.pixel.x, state.probe.pixel.y}},
                                         {"shows_values", state.probe.result.inside}}},
                              {"camera", {{"position", {state.cameraPosition.x, state.cameraPosition.y, state.cameraPosition.z}}}},
                              {"viewport", {{"output", state.viewport.output},
                                            {"zoom", state.viewport.zoom},
                                            {"unavailable", state.viewportImage.unavailable}}},
                              {"reference", referenceReport(session)},
                              {"render_size", {state.renderSize.x, state.renderSize.y}},
                              {"resolution", {{"scale", state.viewport.scale()},
                                              {"auto", state.viewport.resolution == ui::ResolutionScale::Auto},
                                              {"software_start", state.viewport.softwareStart}}},
                              {"wanted_size", {state.wantedSize.x, state.wantedSize.y}},
                              {"frames", state.frame + 1},
                              {"frames_rendered", state.framesRendered},
                              {"last_rendered_frame", static_cast<long long>(state.report.frameIndex)},
                              {"last_timed_frame", lastTimedFrame},
                              {"renderdoc_captures", state.renderdocCaptures},
                              {"banner", state.log.banner() ? state.log.banner()->text : std::string()},
                              {"scene", {{"name", session.scene().name}, {"source", session.scene().source}}},
                              {"recent_scenes", std::vector<std::string>(state.recentScenes.begin(), state.recentScenes.end())},
                              {"active_preset", state.activePreset},
                              {"axes", state.viewport.overlay.axes},
                              {"timings", ui::timingsReport(timer, state)},
                              {"items", itemsReport()},
                              {"errors", errors}};
    writeFileAtomically(path, j.dump(2) + "\n");
}

// Everything the frame loop owns besides the UI: the session and the
// renderer-side helpers that make the images the panels show.
class Frame {
public:
    explicit Frame(RenderSession& session) : session_(session) {
        sideView_.setup(session.shaders());
        forward_.setup(session.shaders());
        overlay_.setup(session.shaders());
        nearest_ = gl::Sampler::create(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, "workbench pixel zoom");
    }
    const gl::Sampler& nearestSampler() const { return nearest_; }

    void render(ui::UiState& state) {
        Pipeline& pipeline = session_.pipeline();
        // The render size: the viewport panel's, times the resolution scale.
        if (state.wantedSize.x > 0) {
            const float scale = state.viewport.scale();
            const glm::ivec2 target(std::max(16, static_cast<int>(std::lround(state.wantedSize.x * scale))),
                                    std::max(16, static_cast<int>(std::lround(state.wantedSize.y * scale))));
            if (target != state.renderSize) {
                session_.resize(target.x, target.y);
                state.renderSize = target;
            }
        }
        state.animator.update(session_.mutableScene(), state.frame);
        // A change being measured: this frame renders the knob values of its
        // side (one measured frame a UI frame, so the window stays responsive).
        bool measuring = false;
        if (state.measure.active()) {
            if (state.viewport.mode != ui::DisplayMode::Deferred)
                state.measure.cancel(session_.knobs(), "cancelled: a forward view runs no deferred pass");
            else
                measuring = state.measure.prepareFrame(session_.knobs());
        }
        // Render only when something the images depend on changed, unless
        // timings are being captured (every frame then).
        const std::string signature = frameSignature(state);
        const bool changed = signature != lastSignature_;
        const bool needed = measuring || state.timingCapture || state.animator.running() || state.forceRender || changed;
        state.forceRender = false;
        // The probe's values describe the image they were read from: another
        // image (a scene opened, the camera moved) with the probe neither
        // hovered nor pinned leaves nothing to show, not the old pixel's values.
        if (changed && !state.probe.hovering && !state.probe.pinned) state.probe = ui::ProbeState{};
        if (needed) {
            lastSignature_ = signature;
            renderImages(state);
            ++state.framesRendered;
            if (measuring) state.measure.frameRendered(state.report.frameIndex);
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
        if (state.measure.state() == ChangeMeasurement::State::Waiting) {
            std::vector<std::string> order;
            for (const auto& rec : state.report.passes) order.push_back(rec.name);
            order.push_back(PassTimer::kFrameSeries);
            state.measure.collect(pipeline.timer(), session_.knobs(), order);
        }
        state.timingsPending = pipeline.timer().pendingFrames() > 0 || state.measure.active();
        if (state.probe.hovering || state.probe.pinned) {
            state.probe.result = probePixel(pipeline, state.probe.pixel.x, state.probe.pixel.y);
            probeLights(state);
        }
    }

    // The lights whose volumes contain the probed surface point.
    void probeLights(ui::UiState& state) {
        ui::ProbeState& p = state.probe;
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

private:
    // Everything a frame's images depend on that the window can change, as bytes.
    std::string frameSignature(const ui::UiState& state) const {
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
        put(session_.knobs().generation());
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
        if (o.lightVolumes && state.viewport.volumes == ui::VolumeFilter::AtProbe)
            for (int i : state.probe.lights) put(i);
        put(state.panels.sideView), text(state.side.output), view(state.side.settingsOr());
        put(state.renderSize.x), put(state.renderSize.y), put(state.shaderGeneration);
        return s;
    }

    // Auto resolution: a step towards the frame-time target every few frames
    // rendered, from the newest GPU frame times; frozen while timings are captured.
    void adjustAutoScale(ui::UiState& state) {
        ui::ViewportView& v = state.viewport;
        if (v.resolution != ui::ResolutionScale::Auto || state.timingCapture || state.measure.active() || state.holdView ||
            state.framesRendered % 4 != 0)
            return;
        const PassTimer::Series* total = session_.pipeline().timer().find(PassTimer::kFrameSeries);
        if (!total || total->samples.size() < 2) return;
        std::vector<float> newest;
        for (auto it = total->samples.rbegin(); it != total->samples.rend() && newest.size() < 3; ++it) newest.push_back(it->gpuMs);
        v.autoScale = ui::nextAutoScale(v.autoScale, computeStats(newest).median, v.frameTargetMs);
    }

    void renderImages(ui::UiState& state) {
        Pipeline& pipeline = session_.pipeline();

        // The final image always; the viewed buffers when they can be produced.
        FrameRequest request;
        std::string viewportWhy, sideWhy;
        const bool deferred = state.viewport.mode == ui::DisplayMode::Deferred;
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
        if (state.panels.sideView) tryAdd(state.side.output, sideWhy);
        state.flameFrame = state.heldFlameFrame.value_or(pipeline.frameIndex());
        animateFlameParticles(session_.mutableScene(), state.flameFrame);
        // The forward preview modes run no deferred pass at all.
        if (deferred) {
            state.report = pipeline.render(session_.camera(), request);
        } else {
            pipeline.bindCamera(session_.camera());
            state.report = {};
        }

        // Viewport image: the final image, a buffer view, or a forward mode; then overlays.
        const gl::Texture* base = nullptr;
        const gl::Texture* depth = nullptr;
        keepHistogram(state.viewportImage);
        if (!deferred) {
            const auto mode = state.viewport.mode == ui::DisplayMode::Textured ? ForwardPreview::Mode::Textured
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
                s.onlySelected = state.viewport.volumes == ui::VolumeFilter::Selected;
                s.onlySubset = state.viewport.volumes == ui::VolumeFilter::AtProbe;
                s.subset = state.probe.lights;
                s.threshold = static_cast<float>(session_.knobs().value(*session_.knobs().find("lighting.threshold")));
                s.sphereSubdivisions = static_cast<int>(session_.knobs().value(*session_.knobs().find("lighting.volume_subdivisions")));
                base = &overlay_.compose(*base, depth, session_.scene(), pipeline.lastCamera(), s);
            }
            state.viewportImage.texture = base->id();
            state.viewportImage.width = base->width();
            state.viewportImage.height = base->height();
        }
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
    static void keepHistogram(ui::ShownImage& img) {
        ui::ShownImage next;
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
    void histogram(const ui::ImageView& view, const PublishedOutput& o, ui::ShownImage& img, const ui::UiState& state) {
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
    void refreshHistograms(ui::UiState& state) {
        Pipeline& pipeline = session_.pipeline();
        if (state.viewport.mode == ui::DisplayMode::Deferred && state.viewportImage.unavailable.empty() && state.framesRendered > 0)
            if (const PublishedOutput* o = pipeline.outputs().find(state.viewport.output)) histogram(state.viewport, *o, state.viewportImage, state);
        if (state.panels.sideView && state.sideImage.unavailable.empty() && state.framesRendered > 0)
            if (const PublishedOutput* o = pipeline.outputs().find(state.side.output)) histogram(state.side, *o, state.sideImage, state);
    }

    RenderSession& session_;
    BufferView sideView_;
    ForwardPreview forward_;
    ViewportOverlay overlay_;
    gl::Sampler nearest_;
    std::string lastSignature_;
    std::string lastConfig_;
};

// The viewer's *save*: the shown output at its own resolution, EXR raw or
// PNG as the view maps it, into the export folder.
void saveShownOutput(ui::ImageView& view, ui::UiState& state, RenderSession& session) {
    const std::string ext = view.saveRequest;
    view.saveRequest.clear();
    if (&view == &state.viewport && state.viewport.mode != ui::DisplayMode::Deferred) {
        state.log.error("save: the textured and wireframe previews are no pipeline output; F12 saves the window", state.time,
                        "save buffer");
        return;
    }
    std::string name = view.output;
    std::replace(name.begin(), name.end(), '.', '_');
    const std::string path = state.exportDir + "/" + name + "-frame" + std::to_string(state.report.frameIndex) + "." + ext;
    try {
        std::error_code ec;
        fs::create_directories(state.exportDir, ec);
        BufferViewSettings s = view.settingsOr();
        s.nearPlane = session.camera().nearPlane;
        s.farPlane = session.camera().farPlane;
        s.reversedDepth = session.pipeline().lastCamera().depth.x > 0.5f;
        session.writeOutput(view.output, path, s);
        state.log.done(view.output + " saved to " + path, state.time, "save buffer");
    } catch (const std::exception& e) {
        state.log.error("cannot save " + view.output + ": " + e.what(), state.time, "save buffer");
    }
}

}  // namespace

int runGui(const GuiOptions& options, Scene scene) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland))
        throw Error("no display (DISPLAY is not set), so the workbench window cannot open; "
                    "use 'deferred-workbench render --scene S --out image.png' to render headless");
    const bool scripted = options.run.frames > 0;
    const ScriptedInput script = options.events.empty() ? ScriptedInput() : ScriptedInput::load(options.events);
    Window window(options.run.width, options.run.height, !scripted, RenderDocCapture::injected());
    // A scripted run (tests, screenshots) neither reads nor writes the saved layout.
    const std::string layoutPath = scripted ? std::string() : configDir() + "/layout.json";
    ImGuiLayer imgui(window.get());
    {
        RenderSession session;
        ui::UiState state;
        state.presetsDir = options.presetsDir.empty() ? configDir() + "/presets" : options.presetsDir;
        state.scenesDir = options.scenesDir;
        state.exportDir = fs::absolute(options.exportDir.empty() ? exportDirDefault() : options.exportDir).string();
        // The same rules as render (RunConfig), and again for every scene opened later.
        state.run = options.run;
        session.setScene(std::move(scene), state.run);
        if (const Preset* p = state.run.preset())
            state.log.info("preset '" + p->name + "': " + std::to_string(p->knobs.size()) + " knobs set", 0.0);
        for (const auto& w : session.scene().warnings) state.log.info("warning: " + w, 0.0);
        state.log.info("GL: " + session.glInfo().renderer + " | " + session.glInfo().version, 0.0);
        state.log.info("shaders: " + session.shaders().root().string() +
                           " (edit and press F5 to reload; DW_SHADER_DIR=FOLDER picks another folder)",
                       0.0);
        // Until the viewport panel reports its size, render at a guess of it.
        state.wantedSize = {static_cast<int>(options.run.width * 0.58f), static_cast<int>(options.run.height * 0.6f)};

        Frame frame(session);
        state.nearestSampler = &frame.nearestSampler();
        if (!options.view.empty()) {
            if (!session.pipeline().outputs().find(options.view))
                throw UsageError("--view: no output '" + options.view + "'; 'deferred-workbench list buffers' lists them");
            state.viewport.show(options.view);
        }
        const ui::StartResolution startScale = ui::startResolution(options.resolution, gl::isCpuRasterizer(session.glInfo()), scripted);
        state.viewport.resolution = startScale.scale;
        state.viewport.autoScale = startScale.autoScale;
        state.viewport.frameTargetMs = startScale.frameTargetMs;
        if (startScale.softwareDefault) {
            state.viewport.softwareStart = session.glInfo().renderer;
            state.log.info("software OpenGL (" + session.glInfo().renderer +
                               "): the viewport starts at auto resolution (1/4, then stepping to keep a frame under 150 ms); "
                               "the toolbar's 'full' button or --resolution full renders every pixel",
                           0.0);
        }
        state.timingCapture = options.record;
        RenderDocCapture renderdoc = RenderDocCapture::attach(false);
        state.renderdocAvailable = renderdoc.available();
        state.renderdocWhy = renderdoc.why();
        if (renderdoc.available()) {
            std::error_code ec;
            fs::create_directories(state.exportDir, ec);
            renderdoc.setPathTemplate(state.exportDir + "/workbench");
            state.log.info("RenderDoc: F11 or Render > Capture frame saves the next frame to " + state.exportDir, 0.0);
            if (!window.eglFailed().empty())
                state.log.error("RenderDoc: no EGL context for the window (" + window.eglFailed() +
                                    "), so it runs on GLX, where RenderDoc 1.24 reports the G-buffer incomplete",
                                0.0);
        }
        int capturesSeen = 0;
        if (!options.openRecord.empty() && !ui::openRecord(state, session, options.openRecord))
            throw Error(state.log.banner() ? state.log.banner()->text : "cannot open record " + options.openRecord);
        ui::WorkbenchUi ui;
        if (!options.layoutIn.empty()) loadLayout(options.layoutIn, ui, state, true);
        else if (!layoutPath.empty()) loadLayout(layoutPath, ui, state);
        std::optional<ImVec2> scriptMouse;
        bool scriptLeft = false, scriptCtrl = false;
        const auto start = std::chrono::steady_clock::now();
        auto last = start;
        while (!glfwWindowShouldClose(window.get()) && !state.requestQuit) {
            const auto t0 = std::chrono::steady_clock::now();
            const float dt = std::min(std::chrono::duration<float>(t0 - last).count(), 0.1f);
            last = t0;
            state.time = std::chrono::duration<double>(t0 - start).count();
            const ScriptedFrameInput in = script.at(static_cast<int>(state.frame));
            if (in.resize) glfwSetWindowSize(window.get(), in.resize->first, in.resize->second);
            glfwPollEvents();
            // Scripted keys and text go through the queue as a person's would.
            for (const auto& [key, mods] : in.keys) {
                for (const auto& [bit, modKey] : kModifierKeys)
                    if (mods & bit) inputQueue().key(modKey, true, mods);
                inputQueue().key(key, true, mods);
                inputQueue().key(key, false, mods);
                for (const auto& [bit, modKey] : kModifierKeys)
                    if (mods & bit) inputQueue().key(modKey, false, 0);
            }
            for (const char32_t c : in.text) {
                const ScriptedKey k = scriptedKeyForChar(c);
                if (k.key >= 0) {
                    if (k.mods) inputQueue().key(GLFW_KEY_LEFT_SHIFT, true, k.mods);
                    inputQueue().key(k.key, true, k.mods);
                }
                inputQueue().character(static_cast<unsigned>(c));
                if (k.key >= 0) {
                    inputQueue().key(k.key, false, k.mods);
                    if (k.mods) inputQueue().key(GLFW_KEY_LEFT_SHIFT, false, 0);
                }
            }
            for (const auto& f : in.drops) droppedFiles().push_back(f);
            for (const auto& a : in.sets) {
                try {
                    session.knobs().applyAssignment(a);
                } catch (const std::exception& e) {
                    state.log.error(e.what(), state.time, "set knob");
                }
            }
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            state.keyPresses = inputQueue().feed(ImGui::GetIO());
            state.droppedFiles.swap(droppedFiles());
            droppedFiles().clear();
            // Scripted input over what the backend read from the (idle) window.
            if (in.mouseX && in.mouseY) scriptMouse = ImVec2(*in.mouseX, *in.mouseY);
            if (in.leftDown) scriptLeft = *in.leftDown;
            if (in.ctrl) scriptCtrl = *in.ctrl;
            if (scriptMouse) {
                ImGuiIO& io = ImGui::GetIO();
                io.MousePos = *scriptMouse;
                io.MouseDown[ImGuiMouseButton_Left] = scriptLeft;
                io.MouseWheel += in.wheel;
                io.KeyCtrl = io.KeyCtrl || scriptCtrl;
            }
            ImGui::NewFrame();
            try {
                frame.render(state);
                state.log.succeeded("render");
            } catch (const std::exception& e) {
                state.log.error(std::string("frame failed: ") + e.what(), state.time, "render");
            }
            state.cameraPosition = session.camera().position;
            ui.draw(state, session, dt);

            for (ui::ImageView* view : {static_cast<ui::ImageView*>(&state.viewport), static_cast<ui::ImageView*>(&state.side)})
                if (!view->saveRequest.empty()) saveShownOutput(*view, state, session);
            if (state.requestReloadShaders) {
                state.requestReloadShaders = false;
                const auto errors = session.shaders().reloadChanged();
                ++state.shaderGeneration;
                if (errors.empty()) state.log.done("shaders reloaded", state.time, "reload shaders");
                for (const auto& e : errors)
                    state.log.error("shader error (the last good program stays in use):\n" + e, state.time, "reload shaders");
            }

            ImGui::Render();
            int fbw = 0, fbh = 0;
            glfwGetFramebufferSize(window.get(), &fbw, &fbh);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fbw, fbh);
            glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

            const bool lastFrame = scripted && static_cast<int>(state.frame) + 1 >= options.run.frames;
            if (state.requestScreenshot || (lastFrame && !options.screenshot.empty())) {
                state.requestScreenshot = false;
                const bool scriptedShot = lastFrame && !options.screenshot.empty();
                std::error_code ec;
                if (!scriptedShot) fs::create_directories(state.exportDir, ec);
                const std::string path = scriptedShot ? options.screenshot
                                                      : state.exportDir + "/screenshot-" + std::to_string(state.frame) + ".png";
                try {
                    writeImage(path, readWindowFramebuffer(fbw, fbh));
                    state.log.done("screenshot saved to " + fs::absolute(path).string(), state.time, "screenshot");
                    if (scripted) std::printf("wrote %s (%dx%d)\n", path.c_str(), fbw, fbh);
                } catch (const std::exception& e) {
                    state.log.error(e.what(), state.time, "screenshot");
                    if (scripted) throw;
                }
            }
            if (state.requestRenderDocCapture) {
                state.requestRenderDocCapture = false;
                if (renderdoc.available()) {
                    renderdoc.triggerCapture();
                    state.forceRender = true;  // the captured frame renders every pass, changed or not
                }
                else state.log.error("no RenderDoc capture: " + renderdoc.why(), state.time, "renderdoc");
            }
            glfwSwapBuffers(window.get());
            // RenderDoc writes a triggered capture at the swap.
            if (renderdoc.available() && renderdoc.captureCount() > capturesSeen) {
                capturesSeen = renderdoc.captureCount();
                state.renderdocCaptures.push_back(renderdoc.lastCapturePath());
                state.log.done("RenderDoc capture saved to " + state.renderdocCaptures.back(), state.time, "renderdoc");
                if (scripted) std::printf("wrote %s (RenderDoc capture)\n", state.renderdocCaptures.back().c_str());
            }
            state.cpuFrameMs.push_back(std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - t0).count());
            if (state.cpuFrameMs.size() > PassTimer::kHistory) state.cpuFrameMs.pop_front();
            if (lastFrame && !options.layoutOut.empty()) {
                writeLayoutReport(options.layoutOut, ui, state, fbw, fbh, session);
                std::printf("wrote %s\n", options.layoutOut.c_str());
            }
            ++state.frame;
            if (lastFrame) break;
            if (!scripted && !options.layoutOut.empty() && (glfwWindowShouldClose(window.get()) || state.requestQuit))
                writeLayoutReport(options.layoutOut, ui, state, fbw, fbh, session);
        }
        if (!layoutPath.empty()) {
            std::error_code ec;
            fs::create_directories(configDir(), ec);
            saveLayout(layoutPath, ui, state);
        }
        if (!options.saveRecord.empty()) {
            if (!ui::saveRecord(state, session, options.saveRecord))
                throw Error(state.log.banner() ? state.log.banner()->text : "cannot save record " + options.saveRecord);
            if (scripted) std::printf("wrote %s\n", options.saveRecord.c_str());
        }
        if (!options.dumpKnobs.empty()) {
            session.writeKnobValues(options.dumpKnobs);
            if (scripted) std::printf("wrote %s\n", options.dumpKnobs.c_str());
        }
    }
    return 0;
}

}  // namespace dw
