#pragma once
// The workbench window's frame loop. runGui (GuiApp) opens the window, sets
// the session, the UI state and the panels up, then hands them to a GuiLoop,
// which runs one frame after another in named parts:
//   pollEvents       the window's events (asleep first for the wait planned
//                    after the last frame), the clock, the frame's scripted input
//   beginUiFrame     ImGui's new frame with the queued input and the scripted pointer
//   backgroundWork   the render size follows the viewport panel, the animation
//                    advances, and the work that renders frames of its own
//                    between UI frames takes its step: a change measured, a
//                    quick sweep, a record's frames (ViewportComposer)
//   renderOnChange   the pipeline rendered when what the images depend on
//                    changed, and the viewport's images made (ViewportComposer)
//   drawUi           the panels drawn (WorkbenchUi; the CPU reference's job is
//                    started and polled there, where F9 and the menu ask for it,
//                    and traces on threads of its own), then their requests carried out
//   present          the UI drawn into the window and swapped; screenshots and
//                    RenderDoc captures
//   planIdleWait     how long the next pollEvents may sleep (FrameWait)
// The loop owns nothing it is given: runGui keeps the window, the session and
// the panels, and writes what is left to write at exit.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <epoxy/gl.h>
// epoxy before GLFW (ScriptedInput.h), so GLFW does not pull in the system GL header.
#include <glm/vec2.hpp>
#include <imgui.h>

#include "app/FrameWait.h"
#include "app/GuiApp.h"
#include "app/RenderDocCapture.h"
#include "app/ScriptedInput.h"
#include "renderer/RenderSession.h"
#include "ui/AovCostGuard.h"
#include "ui/InputQueue.h"
#include "ui/UiState.h"
#include "ui/ViewportComposer.h"
#include "ui/WorkbenchUi.h"

struct GLFWwindow;

namespace dw {

// The window's events as GLFW's callbacks (GuiApp) leave them for the loop:
// the callbacks have no user pointer to reach the loop through (GLFW's is
// ImGui's backend's), so they are kept here, one set a process.
struct WindowEvents {
    // Keys, text and buttons in arrival order, handed to ImGui a change per
    // key or button per frame (ui::InputQueue).
    ui::InputQueue input;
    // Files dropped on the window since the last frame.
    std::vector<std::string> dropped;
    // Input and window events seen by the callbacks: the loop sleeps
    // (FrameWait) only when none came since its last frame.
    std::uint64_t count = 0;
};
WindowEvents& windowEvents();

// What a GuiLoop runs with, all set up and kept by runGui.
struct GuiLoopParts {
    GLFWwindow* window = nullptr;
    const GuiOptions* options = nullptr;
    const ScriptedInput* script = nullptr;  // empty without --events
    RenderSession* session = nullptr;
    ui::UiState* state = nullptr;
    ui::ViewportComposer* composer = nullptr;
    ui::AovCostGuard* aovGuard = nullptr;
    ui::WorkbenchUi* ui = nullptr;
    RenderDocCapture* renderdoc = nullptr;
};

class GuiLoop {
public:
    explicit GuiLoop(const GuiLoopParts& parts);
    // Frames until the window closes, File > Quit, or the last scripted
    // frame (options.run.frames > 0). Throws what a scripted run cannot go
    // on from (a screenshot or --layout-out that cannot be written).
    void run();

private:
    // One frame, its parts in order; false after the last scripted frame.
    bool frame();
    void pollEvents();
    void beginUiFrame();
    void backgroundWork();
    void renderOnChange();
    void drawUi();
    void present();
    // The frame's CPU time kept; the frame counted; --layout-out after the last scripted frame.
    bool endFrame();
    void planIdleWait();
    // --layout-out of a window run (not scripted) as it closes.
    void reportOnClose();

    // Parts of a frame's parts.
    void feedScriptedInput();
    void applyScriptedPointer();
    void carryOutRequests();
    void saveShownOutput(ui::ImageView& view);
    void saveScreenshot(bool scriptedShot);
    void triggerRenderDocCapture();
    void noteRenderDocCapture();
    FrameActivity activityAfterFrame() const;
    bool lastFrame() const;

    GLFWwindow* window_;
    const GuiOptions& options_;
    const ScriptedInput& script_;
    RenderSession& session_;
    ui::UiState& state_;
    ui::ViewportComposer& composer_;
    ui::AovCostGuard& aovGuard_;
    ui::WorkbenchUi& ui_;
    RenderDocCapture& renderdoc_;
    const bool scripted_;

    using Clock = std::chrono::steady_clock;
    Clock::time_point start_, last_, frameStart_;
    float dt_ = 0.0f;                   // seconds since the last frame, at most 0.1
    ScriptedFrameInput input_;          // this frame's scripted input
    std::uint64_t renderedBefore_ = 0;  // state.framesRendered as the frame began
    // The scripted pointer, over what the backend read from the (idle) window:
    // it stays where the script last put it.
    std::optional<ImVec2> pointerPos_;
    bool pointerLeft_ = false, pointerCtrl_ = false;
    glm::ivec2 framebuffer_{0, 0};  // the window's framebuffer as last presented
    int capturesSeen_ = 0;          // RenderDoc captures already noted
    FrameWait frameWait_;
    double waitSeconds_ = 0.0;      // the next pollEvents' sleep (0: poll)
    std::uint64_t eventsSeen_ = 0;  // windowEvents().count after the last frame
};

}  // namespace dw
