#include "app/GuiLoop.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/LayoutReport.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/io/ImageIO.h"

namespace dw {

namespace fs = std::filesystem;

WindowEvents& windowEvents() {
    static WindowEvents events;
    return events;
}

GuiLoop::GuiLoop(const GuiLoopParts& parts)
    : window_(parts.window),
      options_(*parts.options),
      script_(*parts.script),
      session_(*parts.session),
      state_(*parts.state),
      composer_(*parts.composer),
      aovGuard_(*parts.aovGuard),
      ui_(*parts.ui),
      renderdoc_(*parts.renderdoc),
      scripted_(parts.options->run.frames > 0) {}

void GuiLoop::run() {
    start_ = Clock::now();
    last_ = start_;
    eventsSeen_ = windowEvents().count;
    while (!glfwWindowShouldClose(window_) && !state_.requestQuit) {
        if (!frame()) break;
        planIdleWait();
        reportOnClose();
    }
}

bool GuiLoop::frame() {
    pollEvents();
    beginUiFrame();
    // An AOV state that would take minutes a frame is refused before it renders (issue 22).
    aovGuard_.beforeFrame(state_, session_);
    try {
        backgroundWork();
        renderOnChange();
        state_.log.succeeded("render");
    } catch (const std::exception& e) {
        state_.log.error(std::string("frame failed: ") + e.what(), state_.time, "render");
    }
    state_.cameraPosition = session_.camera().position;
    drawUi();
    present();
    return endFrame();
}

// Asleep until an event or the planned timeout when nothing needs a frame
// (FrameWait); then the clock, and the frame's scripted input: a resize
// carried out at once, keys, text, drops and knob edits fed in.
void GuiLoop::pollEvents() {
    if (waitSeconds_ > 0.0) glfwWaitEventsTimeout(waitSeconds_);
    else glfwPollEvents();
    frameStart_ = Clock::now();
    dt_ = std::min(std::chrono::duration<float>(frameStart_ - last_).count(), 0.1f);
    last_ = frameStart_;
    state_.time = std::chrono::duration<double>(frameStart_ - start_).count();
    input_ = script_.at(static_cast<int>(state_.frame));
    if (input_.resize) {
        glfwSetWindowSize(window_, input_.resize->first, input_.resize->second);
        glfwPollEvents();
    }
    renderedBefore_ = state_.framesRendered;
    feedScriptedInput();
}

// A frame's scripted keys, text, drops and knob edits: keys and text go
// through the input queue as a person's would.
void GuiLoop::feedScriptedInput() {
    ui::InputQueue& queue = windowEvents().input;
    for (const auto& [key, mods] : input_.keys) {
        for (const auto& [bit, modKey] : kModifierKeys)
            if (mods & bit) queue.key(modKey, true, mods);
        queue.key(key, true, mods);
        queue.key(key, false, mods);
        for (const auto& [bit, modKey] : kModifierKeys)
            if (mods & bit) queue.key(modKey, false, 0);
    }
    for (const char32_t c : input_.text) {
        const ScriptedKey k = scriptedKeyForChar(c);
        if (k.key >= 0) {
            if (k.mods) queue.key(GLFW_KEY_LEFT_SHIFT, true, k.mods);
            queue.key(k.key, true, k.mods);
        }
        queue.character(static_cast<unsigned>(c));
        if (k.key >= 0) {
            queue.key(k.key, false, k.mods);
            if (k.mods) queue.key(GLFW_KEY_LEFT_SHIFT, false, 0);
        }
    }
    for (const auto& f : input_.drops) windowEvents().dropped.push_back(f);
    for (const auto& a : input_.sets) {
        try {
            session_.knobs().applyAssignment(a);
        } catch (const std::exception& e) {
            state_.log.error(e.what(), state_.time, "set knob");
        }
    }
}

// ImGui's new frame: the backends', the queued input handed over (a change
// per key or button a frame), the dropped files, the scripted pointer.
void GuiLoop::beginUiFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    WindowEvents& events = windowEvents();
    state_.keyPresses = events.input.feed(ImGui::GetIO());
    state_.droppedFiles.swap(events.dropped);
    events.dropped.clear();
    applyScriptedPointer();
    ImGui::NewFrame();
}

// The scripted pointer, over what the backend read from the (idle) window.
void GuiLoop::applyScriptedPointer() {
    if (input_.mouseX && input_.mouseY) pointerPos_ = ImVec2(*input_.mouseX, *input_.mouseY);
    if (input_.leftDown) pointerLeft_ = *input_.leftDown;
    if (input_.ctrl) pointerCtrl_ = *input_.ctrl;
    if (!pointerPos_) return;
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = *pointerPos_;
    io.MouseDown[ImGuiMouseButton_Left] = pointerLeft_;
    io.MouseWheel += input_.wheel;
    io.KeyCtrl = io.KeyCtrl || pointerCtrl_;
}

void GuiLoop::backgroundWork() {
    composer_.followViewport(state_);
    composer_.stepBackgroundWork(state_);
}

void GuiLoop::renderOnChange() { composer_.renderOnChange(state_); }

void GuiLoop::drawUi() {
    ui_.draw(state_, session_, dt_);
    aovGuard_.draw(state_, session_);
    carryOutRequests();
}

// What the panels asked for this frame that needs the session: buffer saves, a shader reload.
void GuiLoop::carryOutRequests() {
    for (ui::ImageView* view : {static_cast<ui::ImageView*>(&state_.viewport), static_cast<ui::ImageView*>(&state_.side)})
        if (!view->saveRequest.empty()) saveShownOutput(*view);
    if (state_.requestReloadShaders) {
        state_.requestReloadShaders = false;
        const auto errors = session_.shaders().reloadChanged();
        ++state_.shaderGeneration;
        if (errors.empty()) state_.log.done("shaders reloaded", state_.time, "reload shaders");
        for (const auto& e : errors)
            state_.log.error("shader error (the last good program stays in use):\n" + e, state_.time, "reload shaders");
    }
}

// The viewer's *save*: the shown output at its own resolution, EXR raw or
// PNG as the view maps it, into the export folder.
void GuiLoop::saveShownOutput(ui::ImageView& view) {
    const std::string ext = view.saveRequest;
    view.saveRequest.clear();
    if (&view == &state_.viewport && state_.viewport.mode != ui::DisplayMode::Deferred) {
        state_.log.error("save: the textured and wireframe previews are no pipeline output; F12 saves the window", state_.time,
                         "save buffer");
        return;
    }
    std::string name = view.output;
    std::replace(name.begin(), name.end(), '.', '_');
    const std::string path = state_.exportDir + "/" + name + "-frame" + std::to_string(state_.report.frameIndex) + "." + ext;
    try {
        std::error_code ec;
        fs::create_directories(state_.exportDir, ec);
        BufferViewSettings s = view.settingsOr();
        s.nearPlane = session_.camera().nearPlane;
        s.farPlane = session_.camera().farPlane;
        s.reversedDepth = session_.pipeline().lastCamera().depth.x > 0.5f;
        session_.writeOutput(view.output, path, s);
        state_.log.done(view.output + " saved to " + path, state_.time, "save buffer");
    } catch (const std::exception& e) {
        state_.log.error("cannot save " + view.output + ": " + e.what(), state_.time, "save buffer");
    }
}

bool GuiLoop::lastFrame() const { return scripted_ && static_cast<int>(state_.frame) + 1 >= options_.run.frames; }

// The UI drawn into the window; F12's screenshot (or --screenshot's after
// the last scripted frame); RenderDoc's capture triggered and, after the
// swap, noted.
void GuiLoop::present() {
    ImGui::Render();
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_, &fbw, &fbh);
    framebuffer_ = {fbw, fbh};
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fbw, fbh);
    glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    const bool scriptedShot = lastFrame() && !options_.screenshot.empty();
    if (state_.requestScreenshot || scriptedShot) saveScreenshot(scriptedShot);
    if (state_.requestRenderDocCapture) triggerRenderDocCapture();
    glfwSwapBuffers(window_);
    noteRenderDocCapture();
}

// The window's framebuffer as a PNG: --screenshot's path, or F12's in the export folder.
void GuiLoop::saveScreenshot(bool scriptedShot) {
    state_.requestScreenshot = false;
    std::error_code ec;
    if (!scriptedShot) fs::create_directories(state_.exportDir, ec);
    const std::string path = scriptedShot ? options_.screenshot
                                          : state_.exportDir + "/screenshot-" + std::to_string(state_.frame) + ".png";
    try {
        writeImage(path, readWindowFramebuffer(framebuffer_.x, framebuffer_.y));
        state_.log.done("screenshot saved to " + fs::absolute(path).string(), state_.time, "screenshot");
        if (scripted_) std::printf("wrote %s (%dx%d)\n", path.c_str(), framebuffer_.x, framebuffer_.y);
    } catch (const std::exception& e) {
        state_.log.error(e.what(), state_.time, "screenshot");
        if (scripted_) throw;
    }
}

void GuiLoop::triggerRenderDocCapture() {
    state_.requestRenderDocCapture = false;
    if (renderdoc_.available()) {
        renderdoc_.triggerCapture();
        state_.forceRender = true;  // the captured frame renders every pass, changed or not
    }
    else state_.log.error("no RenderDoc capture: " + renderdoc_.why(), state_.time, "renderdoc");
}

// RenderDoc writes a triggered capture at the swap.
void GuiLoop::noteRenderDocCapture() {
    if (!renderdoc_.available() || renderdoc_.captureCount() <= capturesSeen_) return;
    capturesSeen_ = renderdoc_.captureCount();
    state_.renderdocCaptures.push_back(renderdoc_.lastCapturePath());
    state_.log.done("RenderDoc capture saved to " + state_.renderdocCaptures.back(), state_.time, "renderdoc");
    if (scripted_) std::printf("wrote %s (RenderDoc capture)\n", state_.renderdocCaptures.back().c_str());
}

bool GuiLoop::endFrame() {
    state_.cpuFrameMs.push_back(std::chrono::duration<float, std::milli>(Clock::now() - frameStart_).count());
    if (state_.cpuFrameMs.size() > PassTimer::kHistory) state_.cpuFrameMs.pop_front();
    const bool last = lastFrame();
    if (last && !options_.layoutOut.empty()) {
        if (state_.ab.ready) {
            // The two images the A/B numbers were measured on, for `compare FILE.b.png FILE.a.png`.
            writeImage(options_.layoutOut + ".a.png", composer_.abImages().imageA());
            writeImage(options_.layoutOut + ".b.png", composer_.abImages().imageB());
        }
        writeLayoutReport(options_.layoutOut, ui_, state_, framebuffer_.x, framebuffer_.y, session_);
        std::printf("wrote %s\n", options_.layoutOut.c_str());
    }
    ++state_.frame;
    return !last;
}

void GuiLoop::planIdleWait() {
    waitSeconds_ = frameWait_.timeout(activityAfterFrame());
    eventsSeen_ = windowEvents().count;
}

void GuiLoop::reportOnClose() {
    if (!scripted_ && !options_.layoutOut.empty() && (glfwWindowShouldClose(window_) || state_.requestQuit))
        writeLayoutReport(options_.layoutOut, ui_, state_, framebuffer_.x, framebuffer_.y, session_);
}

// What the frame just drawn leaves to do, for FrameWait.
FrameActivity GuiLoop::activityAfterFrame() const {
    const WindowEvents& events = windowEvents();
    const ui::UiState& state = state_;
    FrameActivity a;
    a.scripted = scripted_;
    a.input = events.count != eventsSeen_;
    a.rendered = state.framesRendered != renderedBefore_;
    a.busy = state.timingCapture || state.animator.running() || state.timeline.running() || state.measure.active() ||
             state.sweep.running() || state.attribution.running() || state.fitBudget.running() ||
             state.recordRun.running() || state.timingsPending || state.forceRender || state.requestScreenshot ||
             state.requestRenderDocCapture || state.requestReference || state.requestReloadShaders ||
             state.requestOpenScene || state.requestQuit || !events.dropped.empty() ||
             events.input.pending() > 0;  // fast input handed over a frame at a time (InputQueue)
    a.background = state.referenceProgress >= 0.0;
    const ImGuiIO& io = ImGui::GetIO();
    for (bool down : io.MouseDown) a.held = a.held || down;
    for (bool down : io.KeysDown) a.held = a.held || down;
    a.typing = io.WantTextInput;
    if (const ui::Message* toast = state.log.toast(state.time))
        a.toastLeft = std::max(0.0, toast->time + ui::MessageLog::kToastSeconds - state.time);
    return a;
}

}  // namespace dw
