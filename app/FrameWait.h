#pragma once
// How long the workbench's frame loop may sleep for events before its next
// UI frame (glfwWaitEventsTimeout). Drawn every loop iteration, the UI of an
// untouched 1280x720 window took 3817 frames through the software GL in
// 20 s, 33 CPU seconds on a 2-core machine: idle means idle. The loop polls
// (timeout 0) while anything needs a frame per UI frame, waits briefly while
// work on another thread runs (a CPU reference: its progress bar and its
// end are seen within kBackgroundSeconds), and otherwise sleeps until an
// input event or kIdleSeconds. No GLFW here: the loop asks, GLFW waits.
namespace dw {

// What the loop knows after a UI frame.
struct FrameActivity {
    bool scripted = false;     // gui --frames: runs as fast as it can, never waits
    bool input = false;        // an input or window event arrived since the last frame
    bool rendered = false;     // this UI frame rendered a deferred frame (another may follow: auto scale, A/B)
    bool busy = false;         // work done one frame per UI frame: timing capture, animation, a measured
                               // change, a sweep, a record, timer results pending, a request not yet carried out
    bool background = false;   // work on another thread the window shows: a CPU reference being traced
    bool held = false;         // a mouse button or a key held down (drags, orbiting with the arrows)
    bool typing = false;       // a text field has the keyboard (its cursor blinks)
    double toastLeft = -1.0;   // seconds the toast on show has left (< 0: none)
};

class FrameWait {
public:
    // Frames drawn from an event's on (its own included) before the loop may sleep: Dear ImGui
    // answers some input a frame or two late (hover, a click's release, a
    // popup opening), and a change made in one frame renders in the next.
    static constexpr int kSettleFrames = 3;
    static constexpr double kIdleSeconds = 1.0;        // the longest sleep: whatever was missed shows within it
    static constexpr double kBackgroundSeconds = 0.1;  // while a CPU reference is traced
    static constexpr double kBlinkSeconds = 0.4;       // ImGui's text cursor: 0.8 s on, 0.4 s off

    // Seconds to wait for events before the next frame; 0: poll and go on.
    double timeout(const FrameActivity& a);

private:
    int settle_ = kSettleFrames;  // the first frames after start-up draw too
};

}  // namespace dw
