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
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <tuple>
#include <type_traits>

#include "app/FrameWait.h"
#include "app/RenderDocCapture.h"
#include "app/ScriptedInput.h"
#include "headless/CommandLine.h"
#include "renderer/Error.h"
#include "renderer/gl/Sampler.h"
#include "renderer/io/ImageHistogram.h"
#include "renderer/lighting/LightVolume.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "ui/AovCostGuard.h"
#include "ui/RecordDialog.h"
#include "renderer/inspect/ForwardPreview.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/RenderSession.h"
#include "renderer/passes/ReferencePass.h"
#include "renderer/inspect/ViewportOverlay.h"
#include "ui/InputQueue.h"
#include "ui/PresetsPanel.h"
#include "ui/ViewportComposer.h"
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

// Input and window events seen by the callbacks: the frame loop sleeps
// (FrameWait) only when none came since its last frame.
std::uint64_t& windowEvents() {
    static std::uint64_t count = 0;
    return count;
}

void onKey(GLFWwindow*, int key, int, int action, int mods) {
    ++windowEvents();
    if (action != GLFW_REPEAT) inputQueue().key(key, action == GLFW_PRESS, mods);
}
void onChar(GLFWwindow*, unsigned codepoint) {
    ++windowEvents();
    inputQueue().character(codepoint);
}
void onMouseButton(GLFWwindow* window, int button, int action, int) {
    ++windowEvents();
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    inputQueue().button(button, action == GLFW_PRESS, static_cast<float>(x), static_cast<float>(y));
}
void onDrop(GLFWwindow*, int count, const char** paths) {
    ++windowEvents();
    for (int i = 0; i < count; ++i) droppedFiles().emplace_back(paths[i]);
}
// The rest only count; ImGui's backend reads the cursor itself (1.86) and
// gets the wheel, focus and enter/leave from its own callbacks, called on.
void onCursorPos(GLFWwindow*, double, double) { ++windowEvents(); }
void onScroll(GLFWwindow* window, double x, double y) {
    ++windowEvents();
    ImGui_ImplGlfw_ScrollCallback(window, x, y);
}
void onFocus(GLFWwindow* window, int focused) {
    ++windowEvents();
    ImGui_ImplGlfw_WindowFocusCallback(window, focused);
}
void onCursorEnter(GLFWwindow* window, int entered) {
    ++windowEvents();
    ImGui_ImplGlfw_CursorEnterCallback(window, entered);
}
void onWindowChange(GLFWwindow*, int, int) { ++windowEvents(); }
void onRefresh(GLFWwindow*) { ++windowEvents(); }

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
        glfwSetCursorPosCallback(window, onCursorPos);
        glfwSetScrollCallback(window, onScroll);
        glfwSetWindowFocusCallback(window, onFocus);
        glfwSetCursorEnterCallback(window, onCursorEnter);
        glfwSetWindowSizeCallback(window, onWindowChange);
        glfwSetFramebufferSizeCallback(window, onWindowChange);
        glfwSetWindowRefreshCallback(window, onRefresh);
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
        // An older layout loads what it has (a panel added since keeps its
        // default); what it has and this version cannot use is said, once.
        std::vector<std::string> dropped;
        if (j.contains("layout")) dropped = ui.layout().fromJson(j["layout"]);
        if (j.contains("open") && j["open"].is_object())
            for (auto it = j["open"].begin(); it != j["open"].end(); ++it) {
                bool* f = ui::WorkbenchUi::panelFlag(state.panels, it.key());
                if (f && it.value().is_boolean()) *f = it.value().get<bool>();
                else dropped.push_back("open." + it.key() + (f ? " is not true or false" : ": no such panel"));
            }
        if (!dropped.empty()) {
            std::string what;
            for (const auto& d : dropped) what += (what.empty() ? "" : "; ") + d;
            state.log.info(path + ": saved layout used in part, dropped: " + what + "; the rest is the default", 0.0);
        }
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

// The A/B split's state and numbers, as the viewport shows them.
nlohmann::json abReport(const ui::AbView& ab) {
    auto median = [](std::vector<double> v) -> nlohmann::json {
        if (v.empty()) return nullptr;
        std::sort(v.begin(), v.end());
        return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    };
    auto side = [&](const ui::AbSide& s) {
        return nlohmann::json{{"have_error", s.haveError}, {"rms", s.rms}, {"flip", s.flip}, {"gpu_ms_median", median(s.gpuMs)},
                              {"gpu_frames", s.gpuMs.size()}};
    };
    const char* sources[] = {"pinned", "preset", "reference"};
    const char* displays[] = {"split", "difference", "flip"};
    nlohmann::json j = {{"enabled", ab.enabled},
                        {"source", sources[static_cast<int>(ab.source)]},
                        {"display", displays[static_cast<int>(ab.display)]},
                        {"preset", ab.preset},
                        {"divider", ab.divider},
                        {"divider_x", ab.dividerScreen.x},
                        {"ready", ab.ready},
                        {"unavailable", ab.unavailable},
                        {"describe_b", ab.describeB},
                        {"size", {ab.width, ab.height}},
                        {"rms", ab.rms},
                        {"psnr", std::isfinite(ab.psnr) ? nlohmann::json(ab.psnr) : nlohmann::json(nullptr)},
                        {"mean", ab.meanAbsolute},
                        {"flip", ab.haveFlip ? nlohmann::json(ab.flip) : nlohmann::json(nullptr)},
                        {"a", side(ab.a)},
                        {"b", side(ab.b)}};
    if (ab.gpuDifference.valid())
        j["gpu_difference_ms"] = {ab.gpuDifference.difference, ab.gpuDifference.low, ab.gpuDifference.high};
    return j;
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
                              {"ab", abReport(state.ab)},
                              {"axes", state.viewport.overlay.axes},
                              {"timings", ui::timingsReport(timer, state)},
                              {"items", itemsReport()},
                              {"errors", errors}};
    writeFileAtomically(path, j.dump(2) + "\n");
}

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

// What the frame just drawn leaves to do, for FrameWait.
FrameActivity activityAfterFrame(const ui::UiState& state, bool scripted, bool input, bool rendered) {
    FrameActivity a;
    a.scripted = scripted;
    a.input = input;
    a.rendered = rendered;
    a.busy = state.timingCapture || state.animator.running() || state.measure.active() || state.sweep.running() ||
             state.recordRun.running() || state.timingsPending || state.forceRender || state.requestScreenshot ||
             state.requestRenderDocCapture || state.requestReference || state.requestReloadShaders ||
             state.requestOpenScene || state.requestQuit || !droppedFiles().empty() ||
             inputQueue().pending() > 0;  // fast input handed over a frame at a time (InputQueue)
    a.background = state.referenceProgress >= 0.0;
    const ImGuiIO& io = ImGui::GetIO();
    for (bool down : io.MouseDown) a.held = a.held || down;
    for (bool down : io.KeysDown) a.held = a.held || down;
    a.typing = io.WantTextInput;
    if (const ui::Message* toast = state.log.toast(state.time))
        a.toastLeft = std::max(0.0, toast->time + ui::MessageLog::kToastSeconds - state.time);
    return a;
}

// The window's state at start-up from the options (gui's command line): the
// scene with the run's knobs, the folders, the view, the resolution, the A/B split.
void setUpState(const GuiOptions& options, Scene scene, bool scripted, RenderSession& session, ui::UiState& state) {
    state.presetsDir = options.presetsDir.empty() ? configDir() + "/presets" : options.presetsDir;
    state.scenesDir = options.scenesDir;
    state.exportDir = fs::absolute(options.exportDir.empty() ? exportDirDefault() : options.exportDir).string();
    // The same rules as render (RunConfig), and again for every scene opened later.
    state.run = options.run;
    session.setScene(std::move(scene), state.run);
    if (const Preset* p = state.run.preset()) {
        state.log.info("preset '" + p->name + "': " + std::to_string(p->knobs.size()) + " knobs set", 0.0);
        // The Presets panel shows it (with --set over it, the start-up values).
        ui::rememberPreset(state, session, p->name);
    }
    for (const auto& w : session.scene().warnings) state.log.info("warning: " + w, 0.0);
    state.log.info("GL: " + session.glInfo().renderer + " | " + session.glInfo().version, 0.0);
    state.log.info("shaders: " + session.shaders().root().string() +
                       " (edit and press F5 to reload; DW_SHADER_DIR=FOLDER picks another folder)",
                   0.0);
    // Until the viewport panel reports its size, render at a guess of it.
    state.wantedSize = {static_cast<int>(options.run.width * 0.58f), static_cast<int>(options.run.height * 0.6f)};
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
    if (!options.ab.empty()) {
        state.ab.enabled = true;
        state.ab.source = options.ab == "pinned"      ? ui::AbSource::Pinned
                          : options.ab == "reference" ? ui::AbSource::Reference
                                                      : ui::AbSource::Preset;
        if (state.ab.source == ui::AbSource::Preset) state.ab.preset = options.ab.substr(7);
        state.ab.display = options.abDisplay == "difference" ? ui::AbDisplay::Difference
                           : options.abDisplay == "flip"     ? ui::AbDisplay::Flip
                                                             : ui::AbDisplay::Split;
    }
}

// RenderDoc's in-app API when the process runs under it, its captures going to the export folder.
RenderDocCapture attachRenderDoc(ui::UiState& state, const Window& window) {
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
    return renderdoc;
}

// A frame's scripted keys, text, drops and knob edits: keys and text go
// through the input queue as a person's would.
void feedScriptedInput(const ScriptedFrameInput& in, RenderSession& session, ui::UiState& state) {
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
}

// The scripted pointer, over what the backend read from the (idle) window.
struct ScriptedPointer {
    std::optional<ImVec2> pos;
    bool left = false, ctrl = false;
    void apply(const ScriptedFrameInput& in) {
        if (in.mouseX && in.mouseY) pos = ImVec2(*in.mouseX, *in.mouseY);
        if (in.leftDown) left = *in.leftDown;
        if (in.ctrl) ctrl = *in.ctrl;
        if (!pos) return;
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = *pos;
        io.MouseDown[ImGuiMouseButton_Left] = left;
        io.MouseWheel += in.wheel;
        io.KeyCtrl = io.KeyCtrl || ctrl;
    }
};

// What the panels asked for this frame that needs the session: buffer saves, a shader reload.
void carryOutRequests(ui::UiState& state, RenderSession& session) {
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
}

// The UI drawn into the window; F12's screenshot (or --screenshot's after
// the last scripted frame); RenderDoc's capture triggered and, after the
// swap, noted. Returns the framebuffer's size.
glm::ivec2 presentFrame(GLFWwindow* window, const GuiOptions& options, bool scripted, bool lastFrame, ui::UiState& state,
                        RenderDocCapture& renderdoc, int& capturesSeen) {
    ImGui::Render();
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window, &fbw, &fbh);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fbw, fbh);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
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
    glfwSwapBuffers(window);
    // RenderDoc writes a triggered capture at the swap.
    if (renderdoc.available() && renderdoc.captureCount() > capturesSeen) {
        capturesSeen = renderdoc.captureCount();
        state.renderdocCaptures.push_back(renderdoc.lastCapturePath());
        state.log.done("RenderDoc capture saved to " + state.renderdocCaptures.back(), state.time, "renderdoc");
        if (scripted) std::printf("wrote %s (RenderDoc capture)\n", state.renderdocCaptures.back().c_str());
    }
    return {fbw, fbh};
}

// At exit: the layout saved (not in scripted runs), --save-record measured, --dump-knobs written.
void finishRun(const GuiOptions& options, bool scripted, const std::string& layoutPath, ui::WorkbenchUi& ui,
               ui::UiState& state, RenderSession& session) {
    if (!layoutPath.empty()) {
        std::error_code ec;
        fs::create_directories(configDir(), ec);
        saveLayout(layoutPath, ui, state);
    }
    if (!options.saveRecord.empty()) {
        // Measured here, the window's last state (one Save record... left running stops).
        state.recordRun.cancel(state, session, "the window closed");
        if (!state.recordRun.runNow(state, session, options.saveRecord))
            throw Error(state.log.banner() ? state.log.banner()->text : "cannot save record " + options.saveRecord);
        if (scripted) std::printf("wrote %s\n", options.saveRecord.c_str());
    }
    if (!options.dumpKnobs.empty()) {
        session.writeKnobValues(options.dumpKnobs);
        if (scripted) std::printf("wrote %s\n", options.dumpKnobs.c_str());
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
        setUpState(options, std::move(scene), scripted, session, state);
        ui::ViewportComposer frame(session);
        ui::AovCostGuard aovGuard;
        state.nearestSampler = &frame.nearestSampler();
        RenderDocCapture renderdoc = attachRenderDoc(state, window);
        int capturesSeen = 0;
        // A record that cannot be opened is a message on screen (Messages and the
        // banner) over the start-up scene, as File > Open record... has it.
        if (!options.openRecord.empty() && !ui::openRecord(state, session, options.openRecord))
            std::fprintf(stderr, "gui: --open-record: %s\n",
                         state.log.banner() ? state.log.banner()->text.c_str() : options.openRecord.c_str());
        ui::WorkbenchUi ui;
        if (!options.layoutIn.empty()) loadLayout(options.layoutIn, ui, state, true);
        else if (!layoutPath.empty()) loadLayout(layoutPath, ui, state);
        ScriptedPointer pointer;
        const auto start = std::chrono::steady_clock::now();
        auto last = start;
        FrameWait frameWait;
        double waitSeconds = 0.0;
        std::uint64_t eventsSeen = windowEvents();
        while (!glfwWindowShouldClose(window.get()) && !state.requestQuit) {
            // Asleep until an event or the timeout when nothing needs a frame (FrameWait).
            if (waitSeconds > 0.0) glfwWaitEventsTimeout(waitSeconds);
            else glfwPollEvents();
            const auto t0 = std::chrono::steady_clock::now();
            const float dt = std::min(std::chrono::duration<float>(t0 - last).count(), 0.1f);
            last = t0;
            state.time = std::chrono::duration<double>(t0 - start).count();
            const ScriptedFrameInput in = script.at(static_cast<int>(state.frame));
            if (in.resize) {
                glfwSetWindowSize(window.get(), in.resize->first, in.resize->second);
                glfwPollEvents();
            }
            const std::uint64_t renderedBefore = state.framesRendered;
            feedScriptedInput(in, session, state);
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            state.keyPresses = inputQueue().feed(ImGui::GetIO());
            state.droppedFiles.swap(droppedFiles());
            droppedFiles().clear();
            pointer.apply(in);
            ImGui::NewFrame();
            // An AOV state that would take minutes a frame is refused before it renders (issue 22).
            aovGuard.beforeFrame(state, session);
            try {
                frame.render(state);
                state.log.succeeded("render");
            } catch (const std::exception& e) {
                state.log.error(std::string("frame failed: ") + e.what(), state.time, "render");
            }
            state.cameraPosition = session.camera().position;
            ui.draw(state, session, dt);
            aovGuard.draw(state, session);
            carryOutRequests(state, session);
            const bool lastFrame = scripted && static_cast<int>(state.frame) + 1 >= options.run.frames;
            const glm::ivec2 fb = presentFrame(window.get(), options, scripted, lastFrame, state, renderdoc, capturesSeen);
            state.cpuFrameMs.push_back(std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - t0).count());
            if (state.cpuFrameMs.size() > PassTimer::kHistory) state.cpuFrameMs.pop_front();
            if (lastFrame && !options.layoutOut.empty()) {
                if (state.ab.ready) {
                    // The two images the A/B numbers were measured on, for `compare FILE.b.png FILE.a.png`.
                    writeImage(options.layoutOut + ".a.png", frame.abImages().imageA());
                    writeImage(options.layoutOut + ".b.png", frame.abImages().imageB());
                }
                writeLayoutReport(options.layoutOut, ui, state, fb.x, fb.y, session);
                std::printf("wrote %s\n", options.layoutOut.c_str());
            }
            ++state.frame;
            if (lastFrame) break;
            waitSeconds = frameWait.timeout(activityAfterFrame(state, scripted, windowEvents() != eventsSeen,
                                                               state.framesRendered != renderedBefore));
            eventsSeen = windowEvents();
            if (!scripted && !options.layoutOut.empty() && (glfwWindowShouldClose(window.get()) || state.requestQuit))
                writeLayoutReport(options.layoutOut, ui, state, fb.x, fb.y, session);
        }
        finishRun(options, scripted, layoutPath, ui, state, session);
    }
    return 0;
}

}  // namespace dw
