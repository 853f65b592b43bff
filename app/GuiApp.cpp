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
#include "app/GuiLoop.h"
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

// GLFW's callbacks: the window's events, for the frame loop (GuiLoop's
// WindowEvents: the keys, text and buttons queued in arrival order).
void onKey(GLFWwindow*, int key, int, int action, int mods) {
    ++windowEvents().count;
    if (action != GLFW_REPEAT) windowEvents().input.key(key, action == GLFW_PRESS, mods);
}
void onChar(GLFWwindow*, unsigned codepoint) {
    ++windowEvents().count;
    windowEvents().input.character(codepoint);
}
void onMouseButton(GLFWwindow* window, int button, int action, int) {
    ++windowEvents().count;
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    windowEvents().input.button(button, action == GLFW_PRESS, static_cast<float>(x), static_cast<float>(y));
}
void onDrop(GLFWwindow*, int count, const char** paths) {
    ++windowEvents().count;
    for (int i = 0; i < count; ++i) windowEvents().dropped.emplace_back(paths[i]);
}
// The rest only count; ImGui's backend reads the cursor itself (1.86) and
// gets the wheel, focus and enter/leave from its own callbacks, called on.
void onCursorPos(GLFWwindow*, double, double) { ++windowEvents().count; }
void onScroll(GLFWwindow* window, double x, double y) {
    ++windowEvents().count;
    ImGui_ImplGlfw_ScrollCallback(window, x, y);
}
void onFocus(GLFWwindow* window, int focused) {
    ++windowEvents().count;
    ImGui_ImplGlfw_WindowFocusCallback(window, focused);
}
void onCursorEnter(GLFWwindow* window, int entered) {
    ++windowEvents().count;
    ImGui_ImplGlfw_CursorEnterCallback(window, entered);
}
void onWindowChange(GLFWwindow*, int, int) { ++windowEvents().count; }
void onRefresh(GLFWwindow*) { ++windowEvents().count; }

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
        // A record that cannot be opened is a message on screen (Messages and the
        // banner) over the start-up scene, as File > Open record... has it.
        if (!options.openRecord.empty() && !ui::openRecord(state, session, options.openRecord))
            std::fprintf(stderr, "gui: --open-record: %s\n",
                         state.log.banner() ? state.log.banner()->text.c_str() : options.openRecord.c_str());
        ui::WorkbenchUi ui;
        if (!options.layoutIn.empty()) loadLayout(options.layoutIn, ui, state, true);
        else if (!layoutPath.empty()) loadLayout(layoutPath, ui, state);
        GuiLoop({window.get(), &options, &script, &session, &state, &frame, &aovGuard, &ui, &renderdoc}).run();
        finishRun(options, scripted, layoutPath, ui, state, session);
    }
    return 0;
}

}  // namespace dw
