#pragma once
// The scripted mode's input (gui --events FILE): a short list of timed user
// actions replayed into Dear ImGui's input state, so tests drive the window
// as a person would (click, drag, wheel, keys, window resizes) without a
// window manager or xdotool. One action a line, '#' starts a comment:
//
//   <frame> move X Y              the mouse to window pixel (X, Y)
//   <frame> click X Y             press the left button there, release a frame later
//   <frame> drag X0 Y0 X1 Y1 [N]  press at (X0, Y0), move to (X1, Y1) over N frames (default 4), release
//   <frame> wheel D               scroll D notches (positive: away from the user)
//   <frame> key NAME              press a key: a-z, 0-9, F1-F12, Escape, Enter, Space
//   <frame> resize W H            the window to W x H pixels
//   <frame> ctrl down|up          hold or release Ctrl (zoom and pan in an image view)
//
// Frames count from 0, the first frame the window draws.
#include <optional>
#include <string>
#include <vector>

namespace dw {

struct ScriptedFrameInput {
    std::optional<float> mouseX, mouseY;  // where the mouse is from this frame on
    std::optional<bool> leftDown;         // the left button's state from this frame on
    float wheel = 0.0f;
    std::vector<int> keys;                // GLFW key codes pressed this frame
    std::optional<std::pair<int, int>> resize;
    std::optional<bool> ctrl;             // Ctrl held from this frame on
};

class ScriptedInput {
public:
    // Throws UsageError naming the file, the line and what is wrong.
    static ScriptedInput load(const std::string& path);
    static ScriptedInput parse(const std::string& text, const std::string& source);

    // What changes at `frame` (nothing when the script says nothing of it).
    ScriptedFrameInput at(int frame) const;
    // The last frame any action touches.
    int lastFrame() const;

private:
    struct Event {
        int frame = 0;
        ScriptedFrameInput input;
    };
    std::vector<Event> events_;
};

// "a", "F5", "Escape" -> GLFW key code; -1 when unknown.
int glfwKeyFromName(const std::string& name);

}  // namespace dw
