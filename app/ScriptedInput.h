#pragma once
// The scripted mode's input (gui --events FILE): a short list of timed user
// actions replayed into Dear ImGui's input state, so tests drive the window
// as a person would (click, drag, wheel, keys, window resizes) without a
// window manager or xdotool. One action a line, '#' starts a comment:
//
//   <frame> move X Y              the mouse to window pixel (X, Y)
//   <frame> click X Y             the mouse to (X, Y), press the left button a frame later, release the next
//   <frame> drag X0 Y0 X1 Y1 [N]  press at (X0, Y0), move to (X1, Y1) over N frames (default 4), release
//   <frame> wheel D               scroll D notches (positive: away from the user)
//   <frame> key NAME              press and release a key: a-z, 0-9, F1-F12, Escape, Enter,
//                                 Space, Tab, Backspace, Delete, Home, End, Left, Right, Up,
//                                 Down, PageUp, PageDown; with modifiers: ctrl+a, shift+Tab
//   <frame> type TEXT             type the rest of the line (keys and characters, as a keyboard would;
//                                 at most kMaxTypedBytes, as a drop's path)
//   <frame> drop PATH             drop the file at PATH (the rest of the line) on the window
//   <frame> resize W H            the window to W x H pixels
//   <frame> ctrl down|up          hold or release Ctrl (zoom and pan in an image view)
//   <frame> set KNOB=VALUE        a knob edited, as in the Parameters panel (the registry's checks)
//
// Frames count from 0, the first frame the window draws. Keys, text and
// drops go through the same input queue as the window's own events
// (ui/InputQueue), so a key and its release inside one frame are handed to
// ImGui over frames exactly as a fast typist's would be.
#include <GLFW/glfw3.h>

#include <cstddef>

#include <optional>
#include <string>
#include <vector>

namespace dw {

// The most a `type` or `drop` line may hold (bytes after the action).
constexpr std::size_t kMaxTypedBytes = 4096;

struct ScriptedFrameInput {
    std::optional<float> mouseX, mouseY;  // where the mouse is from this frame on
    std::optional<bool> leftDown;         // the left button's state from this frame on
    float wheel = 0.0f;
    std::vector<std::pair<int, int>> keys;  // GLFW key codes and GLFW_MOD_* bits tapped this frame
    std::u32string text;                  // typed this frame
    std::vector<std::string> drops;       // files dropped on the window this frame
    std::optional<std::pair<int, int>> resize;
    std::optional<bool> ctrl;             // Ctrl held from this frame on
    std::vector<std::string> sets;        // knob=value edits this frame
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

// "a", "F5", "Escape", "Home" -> GLFW key code; -1 when unknown.
int glfwKeyFromName(const std::string& name);

// The key (and Shift) a US keyboard types a character with; key -1 for a
// character typed as text alone.
struct ScriptedKey {
    int key = -1;
    int mods = 0;
};
ScriptedKey scriptedKeyForChar(char32_t c);

// Modifier bits and the key held for each.
inline constexpr std::pair<int, int> kModifierKeys[] = {{GLFW_MOD_CONTROL, GLFW_KEY_LEFT_CONTROL},
                                                        {GLFW_MOD_SHIFT, GLFW_KEY_LEFT_SHIFT},
                                                        {GLFW_MOD_ALT, GLFW_KEY_LEFT_ALT},
                                                        {GLFW_MOD_SUPER, GLFW_KEY_LEFT_SUPER}};

}  // namespace dw
