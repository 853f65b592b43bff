#include "app/GuiApp.h"

#include <epoxy/gl.h>
// epoxy must come before GLFW so GLFW does not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "renderer/Error.h"
#include "renderer/inspect/ForwardPreview.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/RenderSession.h"
#include "renderer/inspect/ViewportOverlay.h"
#include "ui/WorkbenchUi.h"

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
    Window(int width, int height, bool vsync) {
        glfwSetErrorCallback(onGlfwError);
        if (!glfwInit())
            throw GlUnsupportedError("cannot open a window (" + glfwErrorText() +
                                     "); use 'deferred-workbench render --scene S --out image.png' to render headless");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        window_ = glfwCreateWindow(width, height, "Deferred Workbench", nullptr, nullptr);
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

private:
    GLFWwindow* window_ = nullptr;
};

// Key presses since the last frame; see UiState::keyPresses.
std::vector<std::pair<int, int>>& pendingKeys() {
    static std::vector<std::pair<int, int>> keys;
    return keys;
}

void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
    if (action == GLFW_PRESS) pendingKeys().emplace_back(key, mods);
}

class ImGuiLayer {
public:
    ImGuiLayer(GLFWwindow* window, const std::string& iniPath) : ini_(iniPath) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = ini_.empty() ? nullptr : ini_.c_str();
        ImGui::StyleColorsDark();
        ImGuiStyle& style = ImGui::GetStyle();
        style.WindowRounding = 2.0f;
        style.FrameRounding = 2.0f;
        style.WindowPadding = ImVec2(6, 6);
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        // Ours forwards to ImGui's and also queues the press.
        glfwSetKeyCallback(window, onKey);
        ImGui_ImplOpenGL3_Init("#version 450 core");
    }
    ~ImGuiLayer() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

private:
    std::string ini_;
};

std::string configDir() {
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::string(x) + "/deferred-workbench";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.config/deferred-workbench";
    return ".deferred-workbench";
}

// Everything the frame loop owns besides the UI: the session and the
// renderer-side helpers that make the images the panels show.
class Frame {
public:
    explicit Frame(RenderSession& session) : session_(session) {
        sideView_.setup(session.shaders());
        forward_.setup(session.shaders());
        overlay_.setup(session.shaders());
    }

    void render(ui::UiState& state) {
        Pipeline& pipeline = session_.pipeline();
        if (state.wantedSize.x > 0 && state.wantedSize != state.renderSize) {
            session_.resize(state.wantedSize.x, state.wantedSize.y);
            state.renderSize = state.wantedSize;
        }
        state.animator.update(session_.mutableScene(), state.frame);

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
        animateFlameParticles(session_.mutableScene(), pipeline.frameIndex());
        state.report = pipeline.render(session_.camera(), request);

        // Viewport image: the final image, a buffer view, or a forward mode; then overlays.
        const gl::Texture* base = nullptr;
        const gl::Texture* depth = nullptr;
        state.viewportImage = {};
        if (!deferred) {
            const auto mode = state.viewport.mode == ui::DisplayMode::Textured ? ForwardPreview::Mode::Textured
                                                                              : ForwardPreview::Mode::Wireframe;
            base = &forward_.render(pipeline.gpuScene(), pipeline.width(), pipeline.height(), mode);
            depth = &forward_.depth();
        } else if (!viewportWhy.empty()) {
            state.viewportImage.unavailable = viewportWhy;
        } else {
            const PublishedOutput* o = pipeline.outputs().find(state.viewport.output);
            if (isDisplayReady(*o)) {
                base = o->texture;
            } else {
                BufferViewSettings s = state.viewport.settings;
                s.nearPlane = session_.camera().nearPlane;
                s.farPlane = session_.camera().farPlane;
                s.reversedDepth = pipeline.lastCamera().depth.x > 0.5f;
                base = &session_.bufferView().render(*o, s);
            }
            depth = pipeline.outputs().find("gbuffer.depth")->texture;
        }
        if (base) {
            const OverlaySettings& ov = state.viewport.overlay;
            if (ov.lightVolumes || ov.axes) {
                OverlaySettings s = ov;
                s.threshold = static_cast<float>(session_.knobs().value(*session_.knobs().find("lighting.threshold")));
                base = &overlay_.compose(*base, depth, session_.scene(), pipeline.lastCamera(), s);
            }
            state.viewportImage = {base->id(), base->width(), base->height(), {}};
        }
        state.sideImage = {};
        if (state.panels.sideView) {
            if (!sideWhy.empty()) {
                state.sideImage.unavailable = sideWhy;
            } else if (const PublishedOutput* o = pipeline.outputs().find(state.side.output)) {
                BufferViewSettings s = state.side.settings;
                s.nearPlane = session_.camera().nearPlane;
                s.farPlane = session_.camera().farPlane;
                s.reversedDepth = pipeline.lastCamera().depth.x > 0.5f;
                const gl::Texture& t = isDisplayReady(*o) ? *o->texture : sideView_.render(*o, s);
                state.sideImage = {t.id(), t.width(), t.height(), {}};
            }
        }
        if (state.probe.hovering || state.probe.pinned)
            state.probe.result = probePixel(pipeline, state.probe.pixel.x, state.probe.pixel.y);
    }

private:
    RenderSession& session_;
    BufferView sideView_;
    ForwardPreview forward_;
    ViewportOverlay overlay_;
};

}  // namespace

int runGui(const GuiOptions& options, Scene scene) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland))
        throw Error("no display (DISPLAY is not set), so the workbench window cannot open; "
                    "use 'deferred-workbench render --scene S --out image.png' to render headless");
    const bool scripted = options.run.frames > 0;
    Window window(options.run.width, options.run.height, !scripted);
    // A scripted run (tests, screenshots) neither reads nor writes the saved layout.
    std::string ini;
    if (!scripted) {
        std::error_code ec;
        fs::create_directories(configDir(), ec);
        if (!ec) ini = configDir() + "/imgui.ini";
    }
    ImGuiLayer imgui(window.get(), ini);
    {
        RenderSession session;
        ui::UiState state;
        state.presetsDir = options.presetsDir.empty() ? configDir() + "/presets" : options.presetsDir;
        state.scenesDir = options.scenesDir;
        // The same rules as render (RunConfig), and again for every scene opened later.
        state.run = options.run;
        session.setScene(std::move(scene), state.run);
        if (const Preset* p = state.run.preset())
            state.log.info("preset '" + p->name + "': " + std::to_string(p->knobs.size()) + " knobs set", 0.0);
        for (const auto& w : session.scene().warnings) state.log.info("warning: " + w, 0.0);
        state.log.info("GL: " + session.glInfo().renderer + " | " + session.glInfo().version, 0.0);
        // Until the viewport panel reports its size, render at a guess of it.
        state.wantedSize = {static_cast<int>(options.run.width * 0.58f), static_cast<int>(options.run.height * 0.6f)};

        Frame frame(session);
        ui::WorkbenchUi ui;
        const auto start = std::chrono::steady_clock::now();
        auto last = start;
        while (!glfwWindowShouldClose(window.get()) && !state.requestQuit) {
            const auto t0 = std::chrono::steady_clock::now();
            const float dt = std::min(std::chrono::duration<float>(t0 - last).count(), 0.1f);
            last = t0;
            state.time = std::chrono::duration<double>(t0 - start).count();
            glfwPollEvents();
            state.keyPresses.swap(pendingKeys());
            pendingKeys().clear();
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            try {
                frame.render(state);
            } catch (const std::exception& e) {
                state.log.error(std::string("frame failed: ") + e.what(), state.time);
            }
            ui.draw(state, session, dt);

            if (state.requestReloadShaders) {
                state.requestReloadShaders = false;
                const auto errors = session.shaders().reloadChanged();
                if (errors.empty()) state.log.info("shaders reloaded", state.time);
                for (const auto& e : errors) state.log.error("shader error (the last good program stays in use):\n" + e, state.time);
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
                const std::string path = lastFrame && !options.screenshot.empty()
                                             ? options.screenshot
                                             : "screenshot-" + std::to_string(state.frame) + ".png";
                try {
                    writeImage(path, readWindowFramebuffer(fbw, fbh));
                    state.log.info("wrote " + path, state.time);
                    if (scripted) std::printf("wrote %s (%dx%d)\n", path.c_str(), fbw, fbh);
                } catch (const std::exception& e) {
                    state.log.error(e.what(), state.time);
                    if (scripted) throw;
                }
            }
            glfwSwapBuffers(window.get());
            state.cpuFrameMs.push_back(std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - t0).count());
            if (state.cpuFrameMs.size() > PassTimer::kHistory) state.cpuFrameMs.pop_front();
            ++state.frame;
            if (lastFrame) break;
        }
        if (!options.dumpKnobs.empty()) {
            session.writeKnobValues(options.dumpKnobs);
            if (scripted) std::printf("wrote %s\n", options.dumpKnobs.c_str());
        }
    }
    return 0;
}

}  // namespace dw
