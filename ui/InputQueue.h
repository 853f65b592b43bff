#pragma once
// The window's keyboard and mouse-button events in arrival order, handed to
// Dear ImGui at most one change per key or button per frame.
//
// Dear ImGui 1.86 (Debian 12's) reads key and button *state* once a frame
// (io.KeysDown, io.MouseDown), not events: a key pressed and released inside
// one frame is never seen down. At llvmpipe's frame times, and for any tool
// that types (xdotool), Enter, Home, End, Backspace and Ctrl+A were lost, and
// text typed after Ctrl+A landed inside the old text. ImGui 1.87 added an
// input queue that "trickles" fast input over frames; this is that, for 1.86,
// with the same rules:
//   - a key or button that already changed this frame waits for the next one;
//   - a press away from where the pointer was the frame before waits a frame
//     with the pointer over its point (the move first, as 1.87 trickles it);
//   - after a button changed, keys and text wait (a click that focuses a
//     field lands before what is typed into it);
//   - after text, a key that edits (Enter, Home, Ctrl+A, a modifier) waits,
//     and after such a key (not a modifier), text and every other key wait
//     (Ctrl+O focuses a field a frame before what is typed into it);
//   - keys that only type (letters, digits, punctuation without Ctrl, Alt or
//     Super) carry no order against text: text arrives as characters, so a
//     typed word goes in one frame.
// The key presses it hands over are returned too, in order, for the
// workbench's shortcuts (they see even a tap shorter than a frame).
#include <imgui.h>

#include <deque>
#include <utility>
#include <vector>

namespace dw::ui {

class InputQueue {
public:
    static constexpr int kButtons = 5;

    // GLFW's key codes, GLFW_PRESS / GLFW_RELEASE (repeats are not queued:
    // ImGui repeats held keys itself), GLFW_MOD_* bits.
    void key(int key, bool down, int mods);
    void character(unsigned codepoint);
    // A mouse button changed with the pointer at (x, y), window pixels.
    void button(int button, bool down, float x, float y);

    // This frame's share of the queue into `io`: call after the platform
    // backend's NewFrame (which sets io.MouseDown from the device; the queue's
    // state replaces it) and before ImGui::NewFrame. Returns the key presses
    // handed over (GLFW key, GLFW_MOD_* bits), in order.
    std::vector<std::pair<int, int>> feed(ImGuiIO& io);

    size_t pending() const { return queue_.size(); }
    bool keyDown(int key) const;

private:
    struct Event {
        enum Kind { Key, Char, Button } kind = Key;
        int code = 0;  // key, codepoint or button
        bool down = false;
        int mods = 0;
        ImVec2 pos{0.0f, 0.0f};
    };
    static bool typesOnly(const Event& e);
    static bool isModifier(int key);

    std::deque<Event> queue_;
    std::vector<int> keysDown_;
    bool buttonsDown_[kButtons] = {};
    ImVec2 lastPos_{-FLT_MAX, -FLT_MAX};  // the pointer handed to ImGui last frame
};

}  // namespace dw::ui
